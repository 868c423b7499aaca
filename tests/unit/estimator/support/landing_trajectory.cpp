#include "landing_trajectory.hpp"

#include <stdexcept>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator::test {

namespace {
// Times within this of a phase boundary count as after it: the IMU samples on the microsecond grid
// and the boundaries are computed in seconds.
constexpr double kTimeEpsilon = 1e-9;
}  // namespace

LandingTrajectory::LandingTrajectory(const LandingSpec& spec) : spec_(spec) {
  const double v = spec.sink_speed;
  // Height lost: v T / 2 over the ramp, v d / 2 during the impact, the rest at the sink speed.
  const double cruise = (spec.start.z() - 0.5 * v * spec.ramp_time - 0.5 * v * spec.impact_duration) / v;
  descent_start_ = impactStart() - cruise - spec.ramp_time;
  if (!(v > 0.0 && cruise >= 0.0 && descent_start_ >= 0.0)) {
    throw std::invalid_argument("LandingTrajectory: the descent does not fit before touchdown_time");
  }
}

TruthSample LandingTrajectory::at(double t) const {
  const double v = spec_.sink_speed;
  const double impact_start = impactStart();
  double z = spec_.start.z(), vz = 0.0, az = 0.0;
  if (t > spec_.touchdown_time + kTimeEpsilon) {
    z = 0.0;
  } else if (t > impact_start + kTimeEpsilon) {
    // Constant deceleration from -v to 0 over the impact, ending at z = 0.
    const double remaining = spec_.touchdown_time - t;
    az = v / spec_.impact_duration;
    vz = -az * remaining;
    z = 0.5 * az * remaining * remaining;
  } else if (t > descent_start_ + spec_.ramp_time) {
    vz = -v;
    z = 0.5 * v * spec_.impact_duration + v * (impact_start - t);
  } else if (t > descent_start_) {
    // Velocity -v (3u^2 - 2u^3): acceleration continuous, zero at both ends.
    const double T = spec_.ramp_time;
    const double u = (t - descent_start_) / T;
    vz = -v * (3.0 * u * u - 2.0 * u * u * u);
    az = -v * (6.0 * u - 6.0 * u * u) / T;
    z = spec_.start.z() - v * T * (u * u * u - 0.5 * u * u * u * u);
  }
  TruthSample out;
  out.position = Vec3(spec_.start.x(), spec_.start.y(), z);
  out.velocity = Vec3(0.0, 0.0, vz);
  out.acceleration = Vec3(0.0, 0.0, az);
  out.orientation = quat::fromYaw(spec_.yaw);
  // Level: the body z axis is the world's, so the specific force is a + g along it.
  out.specific_force = Vec3(0.0, 0.0, az + spec_.gravity);
  return out;
}

}  // namespace sdlqr::estimator::test
