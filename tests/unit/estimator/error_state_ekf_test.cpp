#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include <cstring>
#include <iostream>

#include "sdlqr/math/kernel_isa.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/estimator/error_state_ekf.hpp"

namespace sdlqr::estimator {
namespace {

NavState boxPlus(NavState x, const ErrorVector& dx) {
  x.position += dx.segment<3>(kErrPos);
  x.velocity += dx.segment<3>(kErrVel);
  x.orientation = quat::multiply(x.orientation, quat::exp(dx.segment<3>(kErrRot)));
  x.gyro_bias += dx.segment<3>(kErrGyroBias);
  x.accel_bias += dx.segment<3>(kErrAccelBias);
  return x;
}

ErrorVector boxMinus(const NavState& a, const NavState& b) {
  ErrorVector d;
  d.segment<3>(kErrPos) = a.position - b.position;
  d.segment<3>(kErrVel) = a.velocity - b.velocity;
  d.segment<3>(kErrRot) = quat::boxMinus(a.orientation, b.orientation);
  d.segment<3>(kErrGyroBias) = a.gyro_bias - b.gyro_bias;
  d.segment<3>(kErrAccelBias) = a.accel_bias - b.accel_bias;
  return d;
}

NavState agileState() {
  NavState x;
  x.position = Vec3(1.0, -2.0, 3.0);
  x.velocity = Vec3(2.5, -1.0, 0.4);
  x.orientation = quat::exp(Vec3(0.5, -0.3, 1.1));
  x.gyro_bias = Vec3(0.01, -0.02, 0.015);
  x.accel_bias = Vec3(-0.05, 0.08, 0.1);
  return x;
}

ImuDelta agileDelta() {
  ImuDelta d;
  d.dt = 0.004;
  d.delta_angle = Vec3(1.5, -2.0, 0.8) * d.dt;      // ~2.6 rad/s
  d.delta_velocity = Vec3(3.0, -4.0, 12.0) * d.dt;  // ~13 m/s^2 specific force
  return d;
}

TEST(ErrorStateEkf, TransitionMatrixMatchesFiniteDifferencesOfThePropagation) {
  // GIVEN an agile state and IMU window
  const NavState x = agileState();
  const ImuDelta delta = agileDelta();
  const Vec3 gravity(0.0, 0.0, -9.81);
  const ErrorCovariance f = errorTransition(x, delta).dense();
  NavState nominal = x;
  propagateNominal(nominal, delta, gravity);

  // WHEN each error direction is perturbed both ways and propagated
  ErrorCovariance numeric;
  const double eps = 1e-6;
  for (int j = 0; j < kErrorDim; ++j) {
    NavState plus = boxPlus(x, eps * ErrorVector::Unit(j));
    NavState minus = boxPlus(x, -eps * ErrorVector::Unit(j));
    propagateNominal(plus, delta, gravity);
    propagateNominal(minus, delta, gravity);
    numeric.col(j) = (boxMinus(plus, nominal) - boxMinus(minus, nominal)) / (2.0 * eps);
  }

  // THEN the analytic transition agrees with the central differences
  const double worst = (f - numeric).cwiseAbs().maxCoeff();
  std::cout << "[ measured ] max |F - F_numeric| = " << worst << "\n";
  EXPECT_LT(worst, 1e-7);
}

TEST(ErrorStateEkf, TheBlockwiseCovarianceTransformIsTheDenseProduct) {
  // GIVEN the transition of an agile window and a full covariance
  const ErrorTransition f = errorTransition(agileState(), agileDelta());
  std::srand(7);
  const ErrorCovariance a = ErrorCovariance::Random();
  const ErrorCovariance p = a * a.transpose() + ErrorCovariance::Identity();

  // THEN the block-wise F P F^T is the dense one to rounding
  const ErrorCovariance dense = f.dense() * p * f.dense().transpose();
  EXPECT_LT((transformedCovariance(f, p) - dense).norm(), 1e-13 * dense.norm());
}

// F P F^T as Eigen expressions evaluated it before issue 26 (lazy 3x3-by-3x15 products added one
// after the other): the sums transformedCovariance() must reproduce to the last bit, or every
// flight would change.
ErrorCovariance eigenExpressionTransform(const ErrorTransition& f, const ErrorCovariance& p) {
  ErrorCovariance fp;
  fp.middleRows<3>(kErrPos) = p.middleRows<3>(kErrPos) + f.pos_vel * p.middleRows<3>(kErrVel) +
                              f.pos_rot * p.middleRows<3>(kErrRot) + f.pos_accel_bias * p.middleRows<3>(kErrAccelBias);
  fp.middleRows<3>(kErrVel) = p.middleRows<3>(kErrVel) + f.vel_rot * p.middleRows<3>(kErrRot) +
                              f.vel_accel_bias * p.middleRows<3>(kErrAccelBias);
  fp.middleRows<3>(kErrRot) = f.rot_rot * p.middleRows<3>(kErrRot) + f.rot_gyro_bias * p.middleRows<3>(kErrGyroBias);
  fp.middleRows<6>(kErrGyroBias) = p.middleRows<6>(kErrGyroBias);
  ErrorCovariance out;
  out.middleCols<3>(kErrPos) = fp.middleCols<3>(kErrPos) + fp.middleCols<3>(kErrVel) * f.pos_vel.transpose() +
                               fp.middleCols<3>(kErrRot) * f.pos_rot.transpose() +
                               fp.middleCols<3>(kErrAccelBias) * f.pos_accel_bias.transpose();
  out.middleCols<3>(kErrVel) = fp.middleCols<3>(kErrVel) + fp.middleCols<3>(kErrRot) * f.vel_rot.transpose() +
                               fp.middleCols<3>(kErrAccelBias) * f.vel_accel_bias.transpose();
  out.middleCols<3>(kErrRot) =
      fp.middleCols<3>(kErrRot) * f.rot_rot.transpose() + fp.middleCols<3>(kErrGyroBias) * f.rot_gyro_bias.transpose();
  out.middleCols<6>(kErrGyroBias) = fp.middleCols<6>(kErrGyroBias);
  return out;
}

TEST(ErrorStateEkf, TheCovarianceTransformAddsAsTheEigenExpressionItReplaced) {
  // GIVEN many random states, IMU windows and covariances, on SSE2 and on the CPU's widest vectors
  std::srand(11);
  int differing = 0;
  for (int n = 0; n < 2000; ++n) {
    setKernelIsa(n % 2 == 0 ? KernelIsa::kBaseline : bestKernelIsa());
    NavState x = agileState();
    x.orientation = quat::exp(Vec3::Random() * 3.0);
    x.velocity = 5.0 * Vec3::Random();
    ImuDelta delta = agileDelta();
    delta.delta_angle = Vec3::Random() * 0.02;
    delta.delta_velocity = Vec3::Random() * 0.1;
    const ErrorCovariance a = ErrorCovariance::Random();
    const ErrorCovariance p = 1e-3 * a * a.transpose() + 1e-4 * ErrorCovariance::Identity();
    const ErrorTransition f = errorTransition(x, delta);
    // THEN the hand-vectorised transform equals the Eigen expressions bit for bit
    const ErrorCovariance fast = transformedCovariance(f, p), reference = eigenExpressionTransform(f, p);
    differing += std::memcmp(fast.data(), reference.data(), sizeof(double) * kErrorDim * kErrorDim) != 0;
  }
  setKernelIsa(bestKernelIsa());
  EXPECT_EQ(differing, 0) << "of 2000 covariances (" << toString(bestKernelIsa()) << " and baseline)";
  // AND the comparison can tell: the same sums added in another order differ in most cases
  const ErrorTransition f = errorTransition(agileState(), agileDelta());
  const ErrorCovariance a = ErrorCovariance::Random();
  const ErrorCovariance p = a * a.transpose();
  const ErrorCovariance reordered = (f.dense() * p) * f.dense().transpose();
  EXPECT_NE(std::memcmp(reordered.data(), eigenExpressionTransform(f, p).data(), sizeof(double) * kErrorDim * kErrorDim), 0);
}

TEST(ErrorStateEkf, PropagationGrowsUncertaintyByTheNoiseModel) {
  // GIVEN a state at rest, level, with zero covariance
  EstimatorParams params;
  const ProcessNoise noise = ProcessNoise::from(params);
  NavState x;
  ErrorCovariance p = ErrorCovariance::Zero();
  ImuDelta rest;
  rest.dt = 0.004;
  rest.delta_velocity = Vec3(0.0, 0.0, 9.81 * rest.dt);
  // WHEN 250 windows (1 s) are propagated
  for (int k = 0; k < 250; ++k) propagate(x, p, rest, noise);
  // THEN the vehicle has not moved, and the attitude (vertical velocity) variance is the white
  // gyro (accelerometer) noise integrated over t = 1 s plus its integrated bias walk, s^2 t^3 / 3
  EXPECT_LT(x.position.norm(), 1e-12);
  EXPECT_LT(x.velocity.norm(), 1e-12);
  const double t = 1.0;
  const double gyro = params.gyro_noise_density, gyro_walk = params.gyro_bias_random_walk;
  const double accel = params.accel_noise_density, accel_walk = params.accel_bias_random_walk;
  // (the discrete sum approximates t^3 / 3 to within 1 % at 250 steps)
  EXPECT_NEAR(p(kErrRot, kErrRot), gyro * gyro * t + gyro_walk * gyro_walk * t * t * t / 3.0, 2e-12);
  EXPECT_NEAR(p(kErrVel + 2, kErrVel + 2), accel * accel * t + accel_walk * accel_walk * t * t * t / 3.0, 2e-10);
  EXPECT_TRUE(p.isApprox(p.transpose()));
  // and the tilt variance feeds horizontal velocity variance through gravity (x only via tilt)
  EXPECT_GT(p(kErrVel, kErrVel), p(kErrVel + 2, kErrVel + 2));
}

TEST(ErrorStateEkf, PoseUpdateIsTheKalmanBlend) {
  // GIVEN independent position uncertainty 2 cm and a pose 5 cm away with 1 cm noise
  NavState x;
  ErrorCovariance p = ErrorCovariance::Identity() * 1e-4;
  p.block<3, 3>(kErrPos, kErrPos) = Mat3::Identity() * 4e-4;
  PoseMeasurement pose;
  pose.position = Vec3(0.05, 0.0, 0.0);
  pose.position_var = 1e-4;
  pose.attitude_var = 1e-4;
  // WHEN it is fused
  const PoseUpdateResult r = updatePose(x, p, pose, 28.0);
  // THEN the estimate moves by P / (P + R) of the offset and the variance shrinks to P R / (P + R)
  ASSERT_TRUE(r.accepted);
  EXPECT_NEAR(r.mahalanobis_sq, 0.05 * 0.05 / 5e-4, 1e-9);
  EXPECT_NEAR(x.position.x(), 0.05 * 0.8, 1e-12);
  EXPECT_NEAR(p(kErrPos, kErrPos), 4e-4 * 1e-4 / 5e-4, 1e-12);
  EXPECT_NEAR(p(kErrRot, kErrRot), 0.5e-4, 1e-12);
  EXPECT_LT((quat::log(x.orientation)).norm(), 1e-15);
}

// The Joseph-form pose update as Eigen expressions computed it before issue 26, its 15x15 results
// on a 16-byte boundary (as GCC placed them): what updatePose() must reproduce to the last bit.
PoseUpdateResult eigenExpressionPoseUpdate(NavState& state, ErrorCovariance& covariance, const PoseMeasurement& pose) {
  using Selection = Eigen::Matrix<double, 6, kErrorDim>;
  using Gain = Eigen::Matrix<double, kErrorDim, 6>;
  PoseVector residual;
  residual.head<3>() = pose.position - state.position;
  residual.tail<3>() = quat::boxMinus(pose.orientation, state.orientation);
  Selection h = Selection::Zero();
  h.block<3, 3>(0, kErrPos) = Mat3::Identity();
  h.block<3, 3>(3, kErrRot) = Mat3::Identity();
  PoseMatrix noise = PoseMatrix::Zero();
  noise.diagonal() << Vec3::Constant(pose.position_var), Vec3::Constant(pose.attitude_var);
  PoseUpdateResult result;
  result.innovation_cov = h * covariance * h.transpose() + noise;
  const Eigen::LLT<PoseMatrix> llt(result.innovation_cov);
  result.mahalanobis_sq = residual.dot(llt.solve(residual));
  result.accepted = true;
  const Gain gain = llt.solve(h * covariance).transpose();
  const ErrorVector correction = gain * residual;
  const ErrorCovariance i_kh = ErrorCovariance::Identity() - gain * h;
  alignas(16) const ErrorCovariance kept = i_kh.lazyProduct(covariance);
  const Gain gain_noise = gain * noise;
  alignas(16) ErrorCovariance updated = kept.lazyProduct(i_kh.transpose()) + gain_noise.lazyProduct(gain.transpose());
  state.position += correction.segment<3>(kErrPos);
  state.velocity += correction.segment<3>(kErrVel);
  const Vec3 dtheta = correction.segment<3>(kErrRot);
  state.orientation = quat::multiply(state.orientation, quat::exp(dtheta)).normalized();
  state.gyro_bias += correction.segment<3>(kErrGyroBias);
  state.accel_bias += correction.segment<3>(kErrAccelBias);
  Mat3 reset = Mat3::Identity();
  reset -= 0.5 * (Mat3() << 0.0, -dtheta[2], dtheta[1], dtheta[2], 0.0, -dtheta[0], -dtheta[1], dtheta[0], 0.0).finished();
  updated.middleRows<3>(kErrRot) = (reset * updated.middleRows<3>(kErrRot)).eval();
  updated.middleCols<3>(kErrRot) = (updated.middleCols<3>(kErrRot) * reset.transpose()).eval();
  covariance = 0.5 * (updated + updated.transpose());
  return result;
}

TEST(ErrorStateEkf, ThePoseUpdateAddsAsTheEigenExpressionsItReplaced) {
  // GIVEN many random states, covariances (full, and diagonal as after a restart) and poses
  std::srand(13);
  int differing = 0;
  for (int n = 0; n < 1000; ++n) {
    NavState x = agileState();
    x.orientation = quat::exp(Vec3::Random() * 3.0);
    const ErrorCovariance a = ErrorCovariance::Random();
    const ErrorCovariance full = 1e-4 * a * a.transpose() + 1e-5 * ErrorCovariance::Identity();
    ErrorCovariance p = 0.5 * (full + full.transpose());  // exactly symmetric, as the filter keeps it
    if (n % 4 == 0) p = (1e-3 * (ErrorVector::Random().array() + 1.5)).matrix().asDiagonal();
    PoseMeasurement pose;
    pose.position = x.position + 0.01 * Vec3::Random();
    pose.orientation = quat::multiply(x.orientation, quat::exp(0.01 * Vec3::Random()));
    pose.position_var = 1e-4 * (1 + n % 3);
    pose.attitude_var = 2e-4;
    // WHEN both fuse it
    NavState fast_state = x, reference_state = x;
    ErrorCovariance fast = p, reference = p;
    const PoseUpdateResult r = updatePose(fast_state, fast, pose, 1e9);
    const PoseUpdateResult expected = eigenExpressionPoseUpdate(reference_state, reference, pose);
    // THEN every number is the same
    const bool same = r.accepted && fast == reference && r.mahalanobis_sq == expected.mahalanobis_sq &&
                      r.innovation_cov == expected.innovation_cov && fast_state.position == reference_state.position &&
                      fast_state.velocity == reference_state.velocity && fast_state.orientation == reference_state.orientation &&
                      fast_state.gyro_bias == reference_state.gyro_bias && fast_state.accel_bias == reference_state.accel_bias;
    differing += !same;
  }
  EXPECT_EQ(differing, 0) << "of 1000 pose updates";
}

TEST(ErrorStateEkf, AttitudeResidualIsLocal) {
  // GIVEN a yawed estimate and a pose rotated by a small body-x rotation from it
  NavState x;
  x.orientation = quat::fromYaw(1.0);
  ErrorCovariance p = ErrorCovariance::Identity() * 1e-2;
  PoseMeasurement pose;
  pose.position = x.position;
  pose.orientation = quat::multiply(x.orientation, quat::exp(Vec3(0.02, 0.0, 0.0)));
  pose.position_var = 1e-4;
  pose.attitude_var = 1e-2;
  // WHEN it is fused with equal prior and measurement variance
  ASSERT_TRUE(updatePose(x, p, pose, 28.0).accepted);
  // THEN the estimate turns half-way about its own x axis
  const Vec3 turned = quat::boxMinus(x.orientation, quat::fromYaw(1.0));
  EXPECT_NEAR(turned.x(), 0.01, 1e-6);
  EXPECT_NEAR(turned.y(), 0.0, 1e-6);
  EXPECT_NEAR(turned.z(), 0.0, 1e-6);
}

TEST(ErrorStateEkf, GateRejectsAnOutlierAndLeavesEverythingUnchanged) {
  NavState x = agileState();
  ErrorCovariance p = ErrorCovariance::Identity() * 1e-4;
  const NavState before = x;
  const ErrorCovariance p_before = p;
  PoseMeasurement pose;
  pose.position = x.position + Vec3(0.0, 0.0, 0.2);  // 0.2 m against a ~1.4 cm innovation std
  pose.orientation = x.orientation;
  pose.position_var = 1e-4;
  pose.attitude_var = 1e-4;
  const PoseUpdateResult r = updatePose(x, p, pose, 28.0);
  EXPECT_FALSE(r.accepted);
  EXPECT_NEAR(r.mahalanobis_sq, 0.04 / 2e-4, 1e-6);
  EXPECT_EQ(x.position, before.position);
  EXPECT_EQ(x.orientation, before.orientation);
  EXPECT_EQ(p, p_before);
}

TEST(ErrorStateEkf, SplitPartsRecomposeTheWindow) {
  const ImuDelta whole = agileDelta();
  const ImuDeltaSplit parts = split(whole, 0.3);
  EXPECT_NEAR(parts.first.dt + parts.rest.dt, whole.dt, 1e-18);
  EXPECT_TRUE((parts.first.delta_angle + parts.rest.delta_angle).isApprox(whole.delta_angle, 1e-15));
  // the rest's delta velocity, rotated back into the window-start frame, completes the whole
  const Vec3 recomposed =
      parts.first.delta_velocity + quat::rotate(quat::exp(parts.first.delta_angle), parts.rest.delta_velocity);
  EXPECT_TRUE(recomposed.isApprox(whole.delta_velocity, 1e-14));
  // and propagating the two parts gives the attitude of propagating the whole
  NavState a = agileState(), b = agileState();
  propagateNominal(a, whole, Vec3(0, 0, -9.81));
  propagateNominal(b, parts.first, Vec3(0, 0, -9.81));
  propagateNominal(b, parts.rest, Vec3(0, 0, -9.81));
  EXPECT_LT(quat::boxMinus(a.orientation, b.orientation).norm(), 1e-14);
  EXPECT_LT((a.velocity - b.velocity).norm(), 1e-5);  // differs only by bias terms of second order
}

TEST(ErrorStateEkf, SplitSharesClippedSamplesInProportion) {
  ImuDelta whole = agileDelta();
  whole.accel_clipped = Vec3(0.0, 2.0, 1.0);
  const ImuDeltaSplit parts = split(whole, 0.25);
  EXPECT_TRUE(parts.first.accel_clipped.isApprox(Vec3(0.0, 0.5, 0.25)));
  EXPECT_TRUE((parts.first.accel_clipped + parts.rest.accel_clipped).isApprox(whole.accel_clipped));
}

TEST(ErrorStateEkf, ClippedSamplesAddTheMissedVelocityVarianceAlongTheirBodyAxis) {
  // GIVEN a tilted state, a window with two samples clipped on the body z axis, and a filter
  // whose only noise source is clipping
  const NavState x = agileState();
  ImuDelta delta = agileDelta();
  ProcessNoise noise;
  noise.gravity = Vec3(0.0, 0.0, -9.81);
  noise.clip_velocity_var = 0.09;
  ErrorCovariance without = ErrorCovariance::Identity() * 1e-4;
  ErrorCovariance with = without;
  NavState a = x, b = x;
  propagate(a, without, delta, noise);
  delta.accel_clipped = Vec3(0.0, 0.0, 2.0);
  propagate(b, with, delta, noise);

  // THEN the state is propagated alike (the missed part has zero mean), and the covariance grows
  // by 2 x 0.09 m^2/s^2 along the world direction of body z, as an impulse at mid-window moves
  // the position by dt / 2 times it
  EXPECT_EQ(a.velocity, b.velocity);
  const Vec3 body_z = quat::bodyZ(x.orientation);
  const Mat3 expected = 0.18 * body_z * body_z.transpose();
  const double dt = delta.dt;
  const ErrorCovariance added = with - without;
  const Mat3 velocity = added.block<3, 3>(kErrVel, kErrVel);
  const Mat3 position_velocity = added.block<3, 3>(kErrPos, kErrVel);
  const Mat3 position = added.block<3, 3>(kErrPos, kErrPos);
  const Mat3 attitude = added.block<3, 3>(kErrRot, kErrRot);
  EXPECT_TRUE(velocity.isApprox(expected, 1e-12));
  EXPECT_TRUE(position_velocity.isApprox(0.5 * dt * expected, 1e-12));
  EXPECT_TRUE(position.isApprox(0.25 * dt * dt * expected, 1e-12));
  EXPECT_LT(attitude.norm(), 1e-15);
  // (nothing is missed across the body z axis)
  const Vec3 across = quat::rotate(x.orientation, Vec3(1.0, 0.0, 0.0));
  EXPECT_NEAR(across.dot(velocity * across), 0.0, 1e-15);
}

}  // namespace
}  // namespace sdlqr::estimator
