#include "sdlqr/estimator/error_state_ekf.hpp"

#include <Eigen/Cholesky>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator {

namespace {

Mat3 skew(const Vec3& v) {
  Mat3 m;
  m << 0.0, -v[2], v[1],
       v[2], 0.0, -v[0],
       -v[1], v[0], 0.0;
  return m;
}

}  // namespace

ImuDeltaSplit split(const ImuDelta& delta, double fraction) {
  ImuDeltaSplit out;
  out.first.dt = fraction * delta.dt;
  out.first.delta_angle = fraction * delta.delta_angle;
  out.first.delta_velocity = fraction * delta.delta_velocity;
  out.rest.dt = delta.dt - out.first.dt;
  out.rest.delta_angle = delta.delta_angle - out.first.delta_angle;
  out.first.accel_clipped = fraction * delta.accel_clipped;
  out.rest.accel_clipped = delta.accel_clipped - out.first.accel_clipped;
  // The rest starts where the body has already turned by the first part's angle.
  out.rest.delta_velocity =
      quat::rotationMatrix(quat::exp(out.first.delta_angle)).transpose() * ((1.0 - fraction) * delta.delta_velocity);
  return out;
}

ProcessNoise ProcessNoise::from(const EstimatorParams& params) {
  ProcessNoise n;
  n.gyro_var = params.gyro_noise_density * params.gyro_noise_density;
  n.accel_var = params.accel_noise_density * params.accel_noise_density;
  n.gyro_bias_var = params.gyro_bias_random_walk * params.gyro_bias_random_walk;
  n.accel_bias_var = params.accel_bias_random_walk * params.accel_bias_random_walk;
  n.clip_velocity_var = params.clip_velocity_std * params.clip_velocity_std;
  n.gravity = Vec3(0.0, 0.0, -params.gravity);
  return n;
}

void propagateNominal(NavState& state, const ImuDelta& delta, const Vec3& gravity) {
  const double dt = delta.dt;
  const Vec3 dtheta = delta.delta_angle - state.gyro_bias * dt;
  const Vec3 dvel_world = quat::rotate(state.orientation, delta.delta_velocity - state.accel_bias * dt);
  // Constant acceleration over the interval: p gains v dt + a dt^2 / 2 with a = dvel_world / dt + g.
  state.position += state.velocity * dt + 0.5 * dt * dvel_world + 0.5 * dt * dt * gravity;
  state.velocity += dvel_world + gravity * dt;
  state.orientation = quat::multiply(state.orientation, quat::exp(dtheta)).normalized();
}

ErrorCovariance errorTransition(const NavState& state, const ImuDelta& delta) {
  const double dt = delta.dt;
  const Vec3 dtheta = delta.delta_angle - state.gyro_bias * dt;
  const Vec3 dvel = delta.delta_velocity - state.accel_bias * dt;
  const Mat3 rot = quat::rotationMatrix(state.orientation);
  // Order [dp, dv, dtheta, dbg, dba]. With R_true = R Exp(dtheta), the world velocity increment
  // R_true (dvel - dba dt) = R dvel - R [dvel]x dtheta - R dt dba; the local attitude error is
  // carried back through the turn, and a gyro bias error acts on the turn through the right
  // Jacobian of Exp (first order: I - [dtheta]x / 2).
  ErrorCovariance f = ErrorCovariance::Identity();
  const Mat3 rot_dvel_skew = rot * skew(dvel);
  f.block<3, 3>(kErrPos, kErrVel) = dt * Mat3::Identity();
  f.block<3, 3>(kErrPos, kErrRot) = -0.5 * dt * rot_dvel_skew;
  f.block<3, 3>(kErrPos, kErrAccelBias) = -0.5 * dt * dt * rot;
  f.block<3, 3>(kErrVel, kErrRot) = -rot_dvel_skew;
  f.block<3, 3>(kErrVel, kErrAccelBias) = -dt * rot;
  f.block<3, 3>(kErrRot, kErrRot) = quat::rotationMatrix(quat::exp(dtheta)).transpose();
  f.block<3, 3>(kErrRot, kErrGyroBias) = -dt * (Mat3::Identity() - 0.5 * skew(dtheta));
  return f;
}

// Eigen sends a dense 15x15 product to its general GEMM kernel (packing, blocking): a third of a
// batch flight's CPU went there. F's 3x3 blocks make it 3x3-by-3x15 products, a quarter of the work.
ErrorCovariance transformedCovariance(const ErrorCovariance& f, const ErrorCovariance& p) {
  const auto block = [&f](int row, int col) { return f.block<3, 3>(row, col); };
  ErrorCovariance fp;
  fp.middleRows<3>(kErrPos) = p.middleRows<3>(kErrPos) + block(kErrPos, kErrVel) * p.middleRows<3>(kErrVel) +
                              block(kErrPos, kErrRot) * p.middleRows<3>(kErrRot) +
                              block(kErrPos, kErrAccelBias) * p.middleRows<3>(kErrAccelBias);
  fp.middleRows<3>(kErrVel) = p.middleRows<3>(kErrVel) + block(kErrVel, kErrRot) * p.middleRows<3>(kErrRot) +
                              block(kErrVel, kErrAccelBias) * p.middleRows<3>(kErrAccelBias);
  fp.middleRows<3>(kErrRot) =
      block(kErrRot, kErrRot) * p.middleRows<3>(kErrRot) + block(kErrRot, kErrGyroBias) * p.middleRows<3>(kErrGyroBias);
  fp.middleRows<6>(kErrGyroBias) = p.middleRows<6>(kErrGyroBias);
  ErrorCovariance out;
  out.middleCols<3>(kErrPos) = fp.middleCols<3>(kErrPos) + fp.middleCols<3>(kErrVel) * block(kErrPos, kErrVel).transpose() +
                               fp.middleCols<3>(kErrRot) * block(kErrPos, kErrRot).transpose() +
                               fp.middleCols<3>(kErrAccelBias) * block(kErrPos, kErrAccelBias).transpose();
  out.middleCols<3>(kErrVel) = fp.middleCols<3>(kErrVel) + fp.middleCols<3>(kErrRot) * block(kErrVel, kErrRot).transpose() +
                               fp.middleCols<3>(kErrAccelBias) * block(kErrVel, kErrAccelBias).transpose();
  out.middleCols<3>(kErrRot) = fp.middleCols<3>(kErrRot) * block(kErrRot, kErrRot).transpose() +
                               fp.middleCols<3>(kErrGyroBias) * block(kErrRot, kErrGyroBias).transpose();
  out.middleCols<6>(kErrGyroBias) = fp.middleCols<6>(kErrGyroBias);
  return out;
}

void propagate(NavState& state, ErrorCovariance& covariance, const ImuDelta& delta, const ProcessNoise& noise) {
  const double dt = delta.dt;
  if (!(dt > 0.0)) return;
  const ErrorCovariance f = errorTransition(state, delta);
  const Mat3 rot = quat::rotationMatrix(state.orientation);
  propagateNominal(state, delta, noise.gravity);

  ErrorCovariance propagated = transformedCovariance(f, covariance);
  // White accelerometer noise integrated once (velocity) and twice (position); isotropic, so the
  // rotation to the world frame leaves it unchanged.
  const Mat3 eye = Mat3::Identity();
  propagated.block<3, 3>(kErrPos, kErrPos) += (noise.accel_var * dt * dt * dt / 3.0) * eye;
  propagated.block<3, 3>(kErrPos, kErrVel) += (noise.accel_var * dt * dt / 2.0) * eye;
  propagated.block<3, 3>(kErrVel, kErrPos) += (noise.accel_var * dt * dt / 2.0) * eye;
  propagated.block<3, 3>(kErrVel, kErrVel) += (noise.accel_var * dt) * eye;
  propagated.block<3, 3>(kErrRot, kErrRot) += (noise.gyro_var * dt) * eye;
  propagated.block<3, 3>(kErrGyroBias, kErrGyroBias) += (noise.gyro_bias_var * dt) * eye;
  propagated.block<3, 3>(kErrAccelBias, kErrAccelBias) += (noise.accel_bias_var * dt) * eye;
  if (!delta.accel_clipped.isZero()) {
    // What a saturated accelerometer missed is unknown in size but confined to the clipped axes;
    // taken as one impulse mid-interval, it moves the position by dt/2 times the velocity.
    const Vec3 missed_var_body = noise.clip_velocity_var * delta.accel_clipped;
    const Mat3 missed = rot * missed_var_body.asDiagonal() * rot.transpose();
    propagated.block<3, 3>(kErrPos, kErrPos) += (0.25 * dt * dt) * missed;
    propagated.block<3, 3>(kErrPos, kErrVel) += (0.5 * dt) * missed;
    propagated.block<3, 3>(kErrVel, kErrPos) += (0.5 * dt) * missed;
    propagated.block<3, 3>(kErrVel, kErrVel) += missed;
  }
  covariance = 0.5 * (propagated + propagated.transpose());
}

PoseUpdateResult updatePose(NavState& state, ErrorCovariance& covariance, const PoseMeasurement& pose,
                            double gate_chi2) {
  using Mat6 = PoseMatrix;
  using Vec6 = PoseVector;
  using Gain = Eigen::Matrix<double, kErrorDim, 6>;
  using Selection = Eigen::Matrix<double, 6, kErrorDim>;

  Vec6 residual;
  residual.head<3>() = pose.position - state.position;
  // q_meas = q (x) Exp(dtheta + noise): the residual is the local rotation from estimate to pose.
  residual.tail<3>() = quat::boxMinus(pose.orientation, state.orientation);

  Selection h = Selection::Zero();
  h.block<3, 3>(0, kErrPos) = Mat3::Identity();
  h.block<3, 3>(3, kErrRot) = Mat3::Identity();
  Mat6 noise = Mat6::Zero();
  noise.diagonal() << Vec3::Constant(pose.position_var), Vec3::Constant(pose.attitude_var);

  const Mat6 innovation_cov = h * covariance * h.transpose() + noise;
  const Eigen::LLT<Mat6> llt(innovation_cov);
  PoseUpdateResult result;
  result.innovation = residual;
  result.innovation_cov = innovation_cov;
  if (llt.info() != Eigen::Success) return result;
  result.mahalanobis_sq = residual.dot(llt.solve(residual));
  if (!(result.mahalanobis_sq <= gate_chi2)) return result;
  result.accepted = true;

  const Gain gain = llt.solve(h * covariance).transpose();  // P H^T S^-1 with P and S symmetric
  const ErrorVector correction = gain * residual;
  // Joseph form keeps P symmetric positive definite despite rounding.
  const ErrorCovariance i_kh = ErrorCovariance::Identity() - gain * h;
  // lazyProduct: coefficient-wise fixed-size products, not Eigen's GEMM path (see above).
  const ErrorCovariance kept = i_kh.lazyProduct(covariance);
  const Gain gain_noise = gain * noise;
  ErrorCovariance updated = kept.lazyProduct(i_kh.transpose()) + gain_noise.lazyProduct(gain.transpose());

  state.position += correction.segment<3>(kErrPos);
  state.velocity += correction.segment<3>(kErrVel);
  const Vec3 dtheta = correction.segment<3>(kErrRot);
  state.orientation = quat::multiply(state.orientation, quat::exp(dtheta)).normalized();
  state.gyro_bias += correction.segment<3>(kErrGyroBias);
  state.accel_bias += correction.segment<3>(kErrAccelBias);

  // Moving the attitude reference by dtheta rotates the remaining attitude error (ESKF reset).
  // G P G^T with G the identity but for its attitude block: only the attitude rows and columns move.
  const Mat3 reset = Mat3::Identity() - 0.5 * skew(dtheta);
  updated.middleRows<3>(kErrRot) = (reset * updated.middleRows<3>(kErrRot)).eval();
  updated.middleCols<3>(kErrRot) = (updated.middleCols<3>(kErrRot) * reset.transpose()).eval();
  covariance = 0.5 * (updated + updated.transpose());
  return result;
}

Vec3 correctedBodyRate(const ImuDelta& delta, const Vec3& gyro_bias) {
  if (!(delta.dt > 0.0)) return Vec3::Zero();
  return delta.delta_angle / delta.dt - gyro_bias;
}

}  // namespace sdlqr::estimator
