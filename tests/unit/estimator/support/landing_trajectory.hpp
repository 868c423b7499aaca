#pragma once
// Test truth for a landing on a hard floor, as sdlqr-sim models it: hover, a smooth descent to a
// constant sink speed, then the ground stops the vehicle within one physics step (a constant
// deceleration over `impact_duration`, ending at touchdown_time), and it rests level. Vertical
// motion only, so the attitude stays level at `yaw` and the body rate is zero.
//
// With impact_duration equal to the IMU period and touchdown_time on the IMU grid, exactly one
// IMU sample (the one at touchdown_time) sees the impact: g + sink_speed / impact_duration, far
// beyond a 16 g accelerometer's range.

#include "analytic_trajectory.hpp"

namespace sdlqr::estimator::test {

struct LandingSpec {
  Vec3 start = Vec3(0.3, -0.2, 0.5);  // [m] hover point; z is the height above the floor (z = 0)
  double yaw = 0.4;                   // [rad]
  double sink_speed = 0.4;            // [m/s] at touchdown
  double ramp_time = 1.0;             // [s] from hover to the sink speed (smoothstep in velocity)
  double touchdown_time = 6.0;        // [s] the end of the impact: from here on at rest
  double impact_duration = 0.001;     // [s] the ground stops the vehicle in one 1 ms physics step
  double gravity = 9.81;              // [m/s^2]
};

class LandingTrajectory {
 public:
  // Throws std::invalid_argument when the descent does not fit between t = 0 and the touchdown.
  explicit LandingTrajectory(const LandingSpec& spec);
  TruthSample at(double t) const;

  const LandingSpec& spec() const { return spec_; }
  double descentStart() const { return descent_start_; }
  double impactStart() const { return spec_.touchdown_time - spec_.impact_duration; }

 private:
  LandingSpec spec_;
  double descent_start_ = 0.0;  // [s]
};

}  // namespace sdlqr::estimator::test
