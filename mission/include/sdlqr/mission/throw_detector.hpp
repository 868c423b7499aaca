#pragma once
// Throw mode, as ArduPilot's (ArduCopter/mode_throw.cpp, "Throw Mode" in the Copter docs): the
// vehicle is armed for a throw with its motors stopped; a throw (or a drop) is recognised from the
// IMU-propagated state estimate, and only then are the motors started, the vehicle levelled and a
// hold commanded where it is. The tests follow ArduPilot's:
//
//   possible throw   (free falling or fast) and changing height (climbing for a throw, sinking
//                    for a drop) and released (the specific force below 1 g: no hand pushes)
//   confirmed        within confirm_window of the possible throw, the vertical velocity has
//                    fallen by confirm_velocity_drop (free fall takes 0.25 s for 2.5 m/s)
//
// The estimate carries no acceleration: it is the difference of the estimated velocities over
// acceleration_window, a fixed ring of the last estimates (no allocation). Clock-free: time is
// the estimate's utime.
//
//   throw_mode: {at: 1.0, type: throw}   # in a scenario file; at < 0 (default): off

#include <array>
#include <cstdint>
#include <optional>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::mission {

enum class ThrowType { kThrow, kDrop };

struct ThrowModeParams {
  double at;                     // [s] armed for a throw from this simulation time; < 0: off
  ThrowType type;
  double vertical_speed;         // [m/s]
  double high_speed;             // [m/s]
  double free_fall_fraction;     // [-] of g: vertical specific force below it is free fall
  double confirm_velocity_drop;  // [m/s]
  double confirm_window;         // [s]
  double acceleration_window;    // [s]

  ThrowModeParams();
  static const ParamTable<ThrowModeParams>& declaration();
  bool enabled() const { return at >= 0.0; }
};

// What the detector decided at a detection: where to hold.
struct ThrowDetection {
  int64_t utime = 0;
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  double yaw = 0.0;
};

class ThrowDetector {
 public:
  ThrowDetector(const ThrowModeParams& params, double gravity);

  // Every initialised estimate; returns the detection once (later estimates: nothing).
  std::optional<ThrowDetection> onEstimate(const StateEstimate& estimate);
  bool detected() const { return detected_; }
  // The test of the last estimate, for tests and the log.
  bool possibleThrow() const { return possible_; }

 private:
  struct Sample {
    int64_t utime = 0;
    Vec3 velocity = Vec3::Zero();
  };
  static constexpr int kRing = 64;  // 0.25 s of STATE_EST at 250 Hz

  bool accelerationOf(const StateEstimate& estimate, Vec3& acceleration) const;

  ThrowModeParams params_;
  double gravity_;
  std::array<Sample, kRing> ring_{};
  int count_ = 0;
  int next_ = 0;
  bool possible_ = false;
  bool detected_ = false;
  int64_t possible_since_utime_ = -1;
  double possible_velocity_z_ = 0.0;
};

}  // namespace sdlqr::mission
