#include "sdlqr/lowlevel/failsafe.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::lowlevel {

FailsafeParams FailsafeParams::load(const ConfigReader& reader) {
  reader.allowOnly({"descent_rate", "velocity_gain", "velocity_integral_gain", "attitude_gain", "max_rate", "thrust_min_ratio", "thrust_max_ratio",
                    "velocity_leak_time", "touchdown_time", "impact_rest_time"});
  FailsafeParams params;
  reader.read("descent_rate", params.descent_rate);
  reader.read("velocity_gain", params.velocity_gain);
  reader.read("velocity_integral_gain", params.velocity_integral_gain);
  reader.read("attitude_gain", params.attitude_gain);
  reader.read("max_rate", params.max_rate);
  reader.read("thrust_min_ratio", params.thrust_min_ratio);
  reader.read("thrust_max_ratio", params.thrust_max_ratio);
  reader.read("velocity_leak_time", params.velocity_leak_time);
  reader.read("touchdown_time", params.touchdown_time);
  reader.read("impact_rest_time", params.impact_rest_time);
  throwIfInvalid(reader, params.invalidReason());
  return params;
}

std::string FailsafeParams::invalidReason() const {
  if (!(descent_rate > 0.0 && descent_rate <= 3.0)) return "descent_rate: must be in (0, 3] m/s";
  if (!(velocity_gain > 0.0 && velocity_gain <= 50.0)) return "velocity_gain: must be in (0, 50] 1/s";
  if (!(velocity_integral_gain >= 0.0 && velocity_integral_gain <= 50.0)) {
    return "velocity_integral_gain: must be in [0, 50] 1/s^2";
  }
  if (!(attitude_gain > 0.0 && attitude_gain <= 50.0)) return "attitude_gain: must be in (0, 50] 1/s";
  if (!(max_rate > 0.0 && max_rate <= 20.0)) return "max_rate: must be in (0, 20] rad/s";
  if (!(thrust_min_ratio >= 0.0 && thrust_min_ratio < 1.0)) return "thrust_min_ratio: must be in [0, 1)";
  if (!(thrust_max_ratio > 1.0 && thrust_max_ratio <= 4.0)) return "thrust_max_ratio: must be in (1, 4]";
  if (!(velocity_leak_time >= 0.0 && std::isfinite(velocity_leak_time))) return "velocity_leak_time: must be >= 0 (0: no leak)";
  if (!(touchdown_time > 0.0 && touchdown_time <= 10.0)) return "touchdown_time: must be in (0, 10] s";
  if (!(impact_rest_time > 0.0 && impact_rest_time <= touchdown_time)) {
    return "impact_rest_time: must be in (0, touchdown_time] s";
  }
  return {};
}

Vec3 levellingRate(const Quat& attitude, double gain, double max_rate) {
  const Vec3 body_z = quat::bodyZ(attitude);
  const Vec3 axis_world = body_z.cross(Vec3::UnitZ());
  const double tilt = std::atan2(axis_world.norm(), body_z.z());
  Vec3 rate = Vec3::Zero();
  if (axis_world.norm() > 1e-9) {
    rate = quat::rotateInverse(attitude, axis_world.normalized()) * (gain * tilt);
  } else if (body_z.z() < 0.0) {
    rate = Vec3(gain * M_PI, 0.0, 0.0);  // exactly inverted: any horizontal axis will do
  }
  // A rotation about body z does not move body z; keep yaw still as the brief asks.
  rate.z() = 0.0;
  const double norm = rate.norm();
  if (norm > max_rate) rate *= max_rate / norm;
  return rate;
}

void Failsafe::engage() {
  rest_time_ = 0.0;
  velocity_integral_ = 0.0;
  impact_seen_ = false;
}

FailsafeOutput Failsafe::step(const Quat& attitude, double vertical_velocity, double hover_thrust,
                              const GroundDetector& ground, double dt) {
  FailsafeOutput out;
  out.body_rate = levellingRate(attitude, params_.attitude_gain, params_.max_rate);

  const double min_thrust = params_.thrust_min_ratio * hover_thrust;
  const double max_thrust = params_.thrust_max_ratio * hover_thrust;
  const double velocity_error = -params_.descent_rate - vertical_velocity;
  const double vertical_thrust = hover_thrust + params_.velocity_gain * velocity_error + velocity_integral_;
  // Tilted, only cos(tilt) of the thrust holds the vehicle up; beyond 60 degrees do not chase it.
  const double cos_tilt = std::max(quat::bodyZ(attitude).z(), 0.5);
  out.thrust = std::clamp(vertical_thrust / cos_tilt, min_thrust, max_thrust);
  const bool pushing_limit = (out.thrust >= max_thrust && velocity_error > 0.0) ||
                             (out.thrust <= min_thrust && velocity_error < 0.0);
  if (!pushing_limit) {
    velocity_integral_ = std::clamp(velocity_integral_ + params_.velocity_integral_gain * velocity_error * dt,
                                    min_thrust - hover_thrust, max_thrust - hover_thrust);
  }

  impact_seen_ = impact_seen_ || ground.impact();
  const bool not_descending = vertical_velocity > -0.5 * params_.descent_rate;
  // Steady descent also looks "at rest" to the accelerometer; only the missing descent tells.
  const bool resting = ground.atRest() && not_descending;
  rest_time_ = resting ? rest_time_ + dt : 0.0;
  out.touched_down = rest_time_ >= (impact_seen_ ? params_.impact_rest_time : params_.touchdown_time);
  return out;
}

}  // namespace sdlqr::lowlevel
