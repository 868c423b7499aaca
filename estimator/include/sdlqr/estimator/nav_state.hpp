#pragma once
// The filter's nominal state and the layout of its 15-dimensional error state.
//
// Attitude error convention (local / right-multiplicative): q_true = q (x) Exp(dtheta), so dtheta
// and the attitude std are expressed in the body frame. Bias errors are true minus estimate.

#include <Eigen/Core>

#include "sdlqr/math/types.hpp"

namespace sdlqr::estimator {

inline constexpr int kErrorDim = 15;
enum ErrorIndex : int { kErrPos = 0, kErrVel = 3, kErrRot = 6, kErrGyroBias = 9, kErrAccelBias = 12 };

using ErrorVector = Eigen::Matrix<double, kErrorDim, 1>;
using ErrorCovariance = Eigen::Matrix<double, kErrorDim, kErrorDim>;

struct NavState {
  Vec3 position = Vec3::Zero();      // [m] world
  Vec3 velocity = Vec3::Zero();      // [m/s] world
  Quat orientation = identityQuat(); // [-] body to world, w x y z
  Vec3 gyro_bias = Vec3::Zero();     // [rad/s] body
  Vec3 accel_bias = Vec3::Zero();    // [m/s^2] body
};

// IMU motion over one interval, integrated from raw samples (biases still in): the PX4 EKF2
// "delta angle / delta velocity" input.
struct ImuDelta {
  double dt = 0.0;                       // [s]
  Vec3 delta_angle = Vec3::Zero();       // [rad] rotation vector, body frame at the interval start
  Vec3 delta_velocity = Vec3::Zero();    // [m/s] integrated specific force, body frame at the interval start
  // Accelerometer samples in the interval that read at the clip level, per body axis: there the
  // delta velocity misses an unknown part of the specific force (a touchdown's impulse).
  Vec3 accel_clipped = Vec3::Zero();     // [samples]
};

// The first `fraction` of an interval and the rest, assuming constant rate and specific force over
// it; the rest's delta velocity is expressed in the body frame at the split point. Clipped samples
// are shared in proportion too (where in the interval they fell is not kept).
struct ImuDeltaSplit {
  ImuDelta first;
  ImuDelta rest;
};
ImuDeltaSplit split(const ImuDelta& delta, double fraction);

}  // namespace sdlqr::estimator
