#pragma once
// Visual-inertial odometry: a noisy pose captured at a fixed rate and published 30-50 ms later.
// The message's utime is the capture time and its pose is the truth of that instant; a
// fixed-capacity delay line holds the poses in flight.

#include <array>
#include <cstdint>
#include <optional>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/sim/random.hpp"
#include "sdlqr/sim/sim_params.hpp"

namespace sdlqr::sim {

class VioModel {
 public:
  VioModel(const VioParams& params, int physics_rate_hz, uint64_t seed);

  // Called once per physics step with the step index (utime = step x period) and the true pose
  // at that step. Captures when a capture is due, and returns the pose whose publish time is
  // this step, if any.
  std::optional<VioPose> step(int64_t step_index, const Vec3& position, const Quat& orientation);

  int inFlight() const { return count_; }

 private:
  struct Pending {
    int64_t publish_step = 0;
    VioPose pose;
  };

  VioParams params_;
  int physics_rate_hz_;
  int64_t period_us_;
  Random noise_;
  Random latency_;
  std::array<Pending, kVioDelayLineCapacity> line_{};
  int head_ = 0;
  int count_ = 0;
  int64_t seq_ = 0;
};

}  // namespace sdlqr::sim
