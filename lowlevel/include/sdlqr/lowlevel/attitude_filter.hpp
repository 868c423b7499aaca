#pragma once
// IMU-only attitude and vertical-velocity estimate that the failsafe flies on when the
// estimator or controller is gone. It runs on every sample all the time, so it is ready.
//
// Attitude: gyro integration corrected towards the accelerometer's "up" (complementary filter).
// On a multirotor the specific force is close to the thrust axis whatever the attitude, except
// in steady flight, so the correction is slow in flight and fast only at rest on the ground.
// Vertical velocity: world-z acceleration integrated with a leak (no position sensor here).
// At rest on the ground the filter learns the gyro bias and the vertical accelerometer offset.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::lowlevel {

// Declared (key, unit, default, range, help) in lowlevel/params/attitude_filter.yaml.
struct AttitudeFilterParams : DeclaredParams<AttitudeFilterParams> {
  double flight_gain;
  double ground_gain;
  double accel_gate;
  double bias_time_constant;
  double velocity_leak_time;

  AttitudeFilterParams();
  static const ParamTable<AttitudeFilterParams>& declaration();
};

class AttitudeFilter {
 public:
  AttitudeFilter(const AttitudeFilterParams& params, double gravity);

  // gyro [rad/s] and accel [m/s^2] in the body frame, dt [s] > 0. `at_rest_on_ground` enables
  // fast levelling and bias learning; `velocity_leak_time` [s] (0: no leak) is chosen by the
  // caller, longer during a failsafe descent, where the leak would otherwise eat the descent.
  void update(const Vec3& gyro, const Vec3& accel, double dt, bool at_rest_on_ground, double velocity_leak_time);

  bool initialized() const { return initialized_; }
  const Quat& attitude() const { return attitude_; }  // body to world, yaw arbitrary at start
  Vec3 bodyRate(const Vec3& gyro) const { return gyro - gyro_bias_; }
  const Vec3& gyroBias() const { return gyro_bias_; }
  double verticalAccelOffset() const { return vertical_accel_offset_; }
  double verticalVelocity() const { return vertical_velocity_; }  // [m/s] world z, up positive
  double verticalAcceleration() const { return vertical_acceleration_; }
  // The vehicle hit something and stopped: a clipped accelerometer spike does not integrate to
  // the velocity it lost, so the caller says so explicitly.
  void stopVertical() { vertical_velocity_ = 0.0; }
  void reset();

 private:
  AttitudeFilterParams params_;
  double gravity_;
  bool initialized_ = false;
  Quat attitude_ = identityQuat();
  Vec3 gyro_bias_ = Vec3::Zero();
  double vertical_accel_offset_ = 0.0;
  double vertical_velocity_ = 0.0;
  double vertical_acceleration_ = 0.0;
};

}  // namespace sdlqr::lowlevel
