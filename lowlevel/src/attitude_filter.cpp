#include "sdlqr/lowlevel/attitude_filter.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/lowlevel/low_pass.hpp"

#include "attitude_filter_rows.hpp"

namespace sdlqr::lowlevel {

AttitudeFilterParams::AttitudeFilterParams() { declaration().setDefaults(*this); }

const ParamTable<AttitudeFilterParams>& AttitudeFilterParams::declaration() {
  static const ParamTable<AttitudeFilterParams> table = attitudeFilterParamsRows();
  return table;
}

namespace {

// The attitude with zero yaw whose body "up" matches the measured specific force.
Quat levelFromSpecificForce(const Vec3& accel) {
  const Vec3 up_body = accel.normalized();
  const Vec3 axis = up_body.cross(Vec3::UnitZ());
  const double angle = std::atan2(axis.norm(), up_body.z());
  if (axis.norm() < 1e-9) return up_body.z() > 0.0 ? identityQuat() : quat::exp(Vec3(M_PI, 0.0, 0.0));
  return quat::exp(axis.normalized() * angle);
}

}  // namespace

AttitudeFilter::AttitudeFilter(const AttitudeFilterParams& params, double gravity) : params_(params), gravity_(gravity) {}

void AttitudeFilter::reset() {
  initialized_ = false;
  attitude_ = identityQuat();
  gyro_bias_.setZero();
  vertical_accel_offset_ = 0.0;
  vertical_velocity_ = 0.0;
  vertical_acceleration_ = 0.0;
}

void AttitudeFilter::update(const Vec3& gyro, const Vec3& accel, double dt, bool at_rest_on_ground,
                            double velocity_leak_time) {
  const double specific_force = accel.norm();
  const bool accel_usable = std::abs(specific_force - gravity_) < params_.accel_gate * gravity_;
  if (!initialized_) {
    attitude_ = accel_usable ? levelFromSpecificForce(accel) : identityQuat();
    initialized_ = true;
  }

  attitude_ = quat::multiply(attitude_, quat::exp(bodyRate(gyro) * dt)).normalized();
  if (accel_usable) {
    // Rotate the measured "up" (world frame) towards world z; the correction has no z part,
    // so yaw, which the accelerometer cannot see, is left alone.
    const Vec3 measured_up = quat::rotate(attitude_, accel / specific_force);
    const double gain = at_rest_on_ground ? params_.ground_gain : params_.flight_gain;
    attitude_ = quat::multiply(quat::exp(gain * dt * measured_up.cross(Vec3::UnitZ())), attitude_).normalized();
  }

  const double world_z_specific_force = quat::rotate(attitude_, accel).z();
  if (at_rest_on_ground) {
    const double alpha = lagAlpha(params_.bias_time_constant, dt);
    gyro_bias_ += alpha * (gyro - gyro_bias_);
    vertical_accel_offset_ += alpha * (world_z_specific_force - gravity_ - vertical_accel_offset_);
    vertical_velocity_ = 0.0;
    vertical_acceleration_ = 0.0;
    return;
  }
  vertical_acceleration_ = world_z_specific_force - gravity_ - vertical_accel_offset_;
  // Implicit leak: stable for any dt.
  const double leak_rate = velocity_leak_time > 0.0 ? 1.0 / velocity_leak_time : 0.0;
  vertical_velocity_ = (vertical_velocity_ + vertical_acceleration_ * dt) / (1.0 + leak_rate * dt);
}

}  // namespace sdlqr::lowlevel
