#pragma once
// Error-state EKF math on NavState: IMU propagation over one ImuDelta and the VIO pose update.
// Free functions on caller-owned state and covariance, fixed-size, no allocation.

#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/estimator/nav_state.hpp"

namespace sdlqr::estimator {

// Continuous-time noise densities squared, taken from EstimatorParams.
struct ProcessNoise {
  double gyro_var = 0.0;        // [rad^2/s]
  double accel_var = 0.0;       // [m^2/s^3]
  double gyro_bias_var = 0.0;   // [rad^2/s^3]
  double accel_bias_var = 0.0;  // [m^2/s^5]
  double clip_velocity_var = 0.0;  // [m^2/s^2] velocity the accelerometer may miss per clipped sample
  Vec3 gravity = Vec3::Zero();  // [m/s^2] world, z up: (0, 0, -g)

  static ProcessNoise from(const EstimatorParams& params);
};

// Advances state and covariance over `delta`, removing the estimated biases from it first. Clipped
// accelerometer samples in `delta` add clip_velocity_var each to the velocity variance along
// their body axis (as an impulse at mid-interval, so position and its correlation follow).
void propagate(NavState& state, ErrorCovariance& covariance, const ImuDelta& delta, const ProcessNoise& noise);
// The same from one state and covariance into others (the history's next entry, written in place;
// the outputs may be the inputs).
void propagate(const NavState& state, const ErrorCovariance& covariance, const ImuDelta& delta, const ProcessNoise& noise,
               NavState& state_out, ErrorCovariance& covariance_out);

// F = d(error after) / d(error before) of one propagation: the identity but for these 3x3 blocks
// (row, column), so F P F^T takes 3x3-by-3x15 products instead of Eigen's 15x15 GEMM path.
struct ErrorTransition {
  Mat3 pos_vel, pos_rot, pos_accel_bias;  // (p,v), (p,theta), (p,ba)
  Mat3 vel_rot, vel_accel_bias;           // (v,theta), (v,ba)
  Mat3 rot_rot, rot_gyro_bias;            // (theta,theta), (theta,bg)
  ErrorCovariance dense() const;
};

// The two halves of propagate(), exposed for the Jacobian test: the nominal state update, and
// F evaluated at `state` (before the update).
void propagateNominal(NavState& state, const ImuDelta& delta, const Vec3& gravity);
ErrorTransition errorTransition(const NavState& state, const ImuDelta& delta);
// F P F^T, exposed for the test that holds it to the dense product.
ErrorCovariance transformedCovariance(const ErrorTransition& f, const ErrorCovariance& p);

struct PoseMeasurement {
  Vec3 position = Vec3::Zero();       // [m] world
  Quat orientation = identityQuat();  // [-] unit, body to world
  double position_var = 0.0;          // [m^2] per axis
  double attitude_var = 0.0;          // [rad^2] per axis
};

using PoseVector = Eigen::Matrix<double, 6, 1>;
using PoseMatrix = Eigen::Matrix<double, 6, 6>;

struct PoseUpdateResult {
  bool accepted = false;
  double mahalanobis_sq = 0.0;  // r^T S^-1 r of the 6-dof innovation
  PoseVector innovation = PoseVector::Zero();             // r: [position (world), attitude (body)]
  PoseMatrix innovation_cov = PoseMatrix::Zero();         // S = H P H^T + R
};

// Fuses a pose taken at the state's time. When the innovation's squared Mahalanobis distance
// exceeds gate_chi2, nothing is changed and accepted is false.
PoseUpdateResult updatePose(NavState& state, ErrorCovariance& covariance, const PoseMeasurement& pose,
                            double gate_chi2);

// Bias-corrected body rate over `delta` (its mean, which is what the rate loop would see).
Vec3 correctedBodyRate(const ImuDelta& delta, const Vec3& gyro_bias);

}  // namespace sdlqr::estimator
