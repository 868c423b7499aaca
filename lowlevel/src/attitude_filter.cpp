#include "sdlqr/lowlevel/attitude_filter.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/lowlevel/low_pass.hpp"
#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::lowlevel {

AttitudeFilterParams AttitudeFilterParams::load(const ConfigReader& reader) {
  reader.allowOnly({"flight_gain", "ground_gain", "accel_gate", "bias_time_constant", "velocity_leak_time"});
  AttitudeFilterParams params;
  reader.read("flight_gain", params.flight_gain);
  reader.read("ground_gain", params.ground_gain);
  reader.read("accel_gate", params.accel_gate);
  reader.read("bias_time_constant", params.bias_time_constant);
  reader.read("velocity_leak_time", params.velocity_leak_time);
  throwIfInvalid(reader, params.invalidReason());
  return params;
}

std::string AttitudeFilterParams::invalidReason() const {
  if (!(flight_gain >= 0.0 && flight_gain <= 50.0)) return "flight_gain: must be in [0, 50] 1/s";
  if (!(ground_gain >= 0.0 && ground_gain <= 50.0)) return "ground_gain: must be in [0, 50] 1/s";
  if (!(accel_gate > 0.0 && accel_gate < 1.0)) return "accel_gate: must be in (0, 1)";
  if (!(bias_time_constant > 0.0 && std::isfinite(bias_time_constant))) return "bias_time_constant: must be > 0";
  if (!(velocity_leak_time >= 0.0 && std::isfinite(velocity_leak_time))) return "velocity_leak_time: must be >= 0 (0: no leak)";
  return {};
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
