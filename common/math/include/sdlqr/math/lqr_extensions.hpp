#pragma once
// The paper's two model extensions (§IV, I and II), each a larger tangent-space model solved by
// the same structure-preserving doubling as the state-dependent LQR (lqr.hpp):
//
//   sdlqr_integral  z = [p, theta, v, xi] (12), xi_dot = p - p_ref: the integral of the position
//                   error, so a constant force (a wrong mass, a steady wind) leaves no steady error.
//   sdlqr_actuator  z = [p, theta, v, c] (10), c_dot = (c_cmd - c) / tau: the collective thrust
//                   lags its command by the first-order time constant tau, so K accounts for it.
//
// Both keep the 4 x 10 K of u = u0 + K (x - x0) for the paper's state and add the gains on the
// extra states in a 4 x 4 block K_aug (columns: xi_x, xi_y, xi_z, c - c0; unused columns zero):
//   u = u0 + K (x - x0) + K_aug [xi; c - c0].
// Fixed-size throughout, no heap allocation.

#include "sdlqr/math/lqr.hpp"

namespace sdlqr {

inline constexpr int kIntegralDim = kTangentDim + 3;  // 12
inline constexpr int kActuatorDim = kTangentDim + 1;  // 10
inline constexpr int kAugIntegral = 0;                // K_aug columns 0..2
inline constexpr int kAugThrust = 3;                  // K_aug column 3

template <int N>
struct AugmentedSystem {
  Eigen::Matrix<double, N, N> A;
  Eigen::Matrix<double, N, kInputDim> B;
  Eigen::Matrix<double, N, N> Q;
};

// The continuous tangent models at (x_lin, u_lin), x_lin's quaternion unit.
AugmentedSystem<kIntegralDim> integralTangentSystem(const State& x_lin, const Input& u_lin, const LqrParams& params);
AugmentedSystem<kActuatorDim> actuatorTangentSystem(const State& x_lin, const Input& u_lin, const LqrParams& params);

struct ExtendedLqrResult {
  LqrResult lqr;            // status, K (the paper's 10 columns), residual, iterations, reason
  Mat4 K_aug = Mat4::Zero();  // zero unless lqr.status == kOk
};

// Solves the model of params.law: the extensions as above; every other law the paper's model
// (solveLqr, bit for bit, K_aug zero). Preconditions and statuses as solveLqr; the tangent
// method only (an extension with method iterative is kInvalidInput).
// thrust_gain: the paper's model's (sdlqr_adaptive, model.hpp linearize); the extensions keep 1.
ExtendedLqrResult solveLqrForLaw(const State& x_lin, const Input& u_lin, const LqrParams& params,
                                 double thrust_gain = 1.0);

// The largest closed-loop eigenvalue modulus of the discretized extended model under (K, K_aug)
// (NaN when not computable): the receiver's own check of an extension's gains.
// dt: discretization step; tau: the actuator model's thrust lag (unused for the integral model);
// drag: the receiver's model's rotor drag (LqrParams::rotorDrag).
double extendedClosedLoopSpectralRadius(ControlLaw law, const State& x_lin, const Input& u_lin, double dt, double tau,
                                        const GainMatrix& K, const Mat4& K_aug, const RotorDrag& drag = {});

}  // namespace sdlqr
