#pragma once
// What the bodyrate loop flies when RATE_CMD goes silent: level the vehicle on the
// IMU-only attitude, hold yaw rate at zero, descend at a fixed rate on the leaky vertical
// velocity with thrust around hover, and report touchdown so the loop can disarm.
// Touchdown: at rest while a descent is commanded but the velocity estimate says the vehicle is
// not descending (the ground holds it); confirmed faster once an impact spike was seen.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"
#include "sdlqr/lowlevel/ground_detector.hpp"

namespace sdlqr::lowlevel {

// Declared (key, unit, default, range, help) in lowlevel/params/failsafe.yaml.
struct FailsafeParams : DeclaredParams<FailsafeParams> {
  double descent_rate;
  double velocity_gain;
  double velocity_integral_gain;
  double attitude_gain;
  double max_rate;
  double thrust_min_ratio;
  double thrust_max_ratio;
  double velocity_leak_time;
  double touchdown_time;
  double impact_rest_time;

  FailsafeParams();
  static const ParamTable<FailsafeParams>& declaration();
};

struct FailsafeOutput {
  Vec3 body_rate = Vec3::Zero();  // [rad/s] setpoint for the rate controller
  double thrust = 0.0;            // [m/s^2] mass-normalized collective
  bool touched_down = false;      // disarm now
};

class Failsafe {
 public:
  explicit Failsafe(const FailsafeParams& params = FailsafeParams()) : params_(params) {}

  // Starts a new descent: clears the touchdown evidence.
  void engage();
  // attitude: body to world; vertical_velocity [m/s] up positive; hover_thrust [m/s^2].
  FailsafeOutput step(const Quat& attitude, double vertical_velocity, double hover_thrust, const GroundDetector& ground,
                      double dt);
  const FailsafeParams& params() const { return params_; }
  double restTime() const { return rest_time_; }
  double velocityIntegral() const { return velocity_integral_; }
  bool impactSeen() const { return impact_seen_; }

 private:
  FailsafeParams params_;
  double rest_time_ = 0.0;
  double velocity_integral_ = 0.0;  // [m/s^2] thrust correction
  bool impact_seen_ = false;
};

// Body rate that turns body z towards world z at `gain` per radian, with no rotation about
// body z, bounded by `max_rate`.
Vec3 levellingRate(const Quat& attitude, double gain, double max_rate);

}  // namespace sdlqr::lowlevel
