#pragma once
// Test truth: an analytic flight whose every derivative is known, so the sensor simulator can
// produce exact specific force and body rates. Hover at `center`, then a figure-eight that fades
// in over `ramp_time` (a C3 envelope, so acceleration and jerk, hence attitude and body rate, are
// continuous). Attitude is the quadrotor's: body z along the required thrust, heading `yaw`.

#include "sdlqr/math/types.hpp"

namespace sdlqr::estimator::test {

struct TruthSample {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Quat orientation = identityQuat();  // body to world
  Vec3 body_rate = Vec3::Zero();      // [rad/s] body
  Vec3 specific_force = Vec3::Zero(); // [m/s^2] body: R^T (a - g)
};

struct TrajectorySpec {
  Vec3 center = Vec3(0.0, 0.0, 1.0);  // [m] hover point and figure-eight centre
  double yaw = 0.3;                   // [rad] heading while hovering
  double hover_time = 2.0;            // [s] before the figure-eight starts
  double ramp_time = 3.0;             // [s] envelope rise
  Vec3 amplitude = Vec3(1.5, 0.75, 0.2);  // [m] x sin(wt), y sin(2wt), z sin(wt): up to ~36 deg tilt, 2.4 rad/s, 3 m/s
  double period = 4.5;                // [s] of one figure-eight
  double yaw_amplitude = 0.3;         // [rad] heading swing, sin(wt)
  double gravity = 9.81;              // [m/s^2]

  static TrajectorySpec hover(const Vec3& center, double yaw);
};

class AnalyticTrajectory {
 public:
  explicit AnalyticTrajectory(const TrajectorySpec& spec) : spec_(spec) {}
  TruthSample at(double t) const;
  const TrajectorySpec& spec() const { return spec_; }

 private:
  struct Kinematics {
    Vec3 p, v, a;
    double yaw;
  };
  Kinematics kinematics(double t) const;
  Quat attitude(const Kinematics& k) const;

  TrajectorySpec spec_;
};

}  // namespace sdlqr::estimator::test
