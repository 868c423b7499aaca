#include "sdlqr/lowlevel/failsafe.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "sdlqr/math/quaternion.hpp"

#include "failsafe_rows.hpp"

namespace sdlqr::lowlevel {

FailsafeParams::FailsafeParams() { declaration().setDefaults(*this); }

const ParamTable<FailsafeParams>& FailsafeParams::declaration() {
  static const ParamTable<FailsafeParams> table = [] {
    using P = FailsafeParams;
    ParamTable<P> t = failsafeParamsRows();
    t.check("impact_rest_time", [](const P& p) { return p.impact_rest_time <= p.touchdown_time; },
            "must be <= touchdown_time");
    return t;
  }();
  return table;
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
