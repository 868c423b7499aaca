#include "sdlqr/math/lqr_extensions.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>

#include "sdlqr/math/discretize.hpp"
#include "sdlqr/math/riccati.hpp"

namespace sdlqr {

namespace {

constexpr int kDefaultMaxDoublings = 64;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

ExtendedLqrResult failure(SolveStatus status, const char* reason, int iterations = 0) {
  ExtendedLqrResult result;
  result.lqr.status = status;
  result.lqr.reason = reason;
  result.lqr.iterations = iterations;
  return result;
}

TangentSystem paperTangentSystem(const State& x_lin, const Input& u_lin, const State& q_diag, const RotorDrag& drag) {
  return projectToTangent(linearize(x_lin, u_lin, 1.0, drag), tangentBasis(orientation(x_lin)), q_diag);
}

// The integral model's continuous matrices without its cost.
void integralDynamics(const TangentSystem& paper, Eigen::Matrix<double, kIntegralDim, kIntegralDim>& A,
                      Eigen::Matrix<double, kIntegralDim, kInputDim>& B) {
  A.setZero();
  B.setZero();
  A.topLeftCorner<kTangentDim, kTangentDim>() = paper.A;
  A.block<3, 3>(kTangentDim, kTanPos).setIdentity();  // xi_dot = p - p_ref
  B.topRows<kTangentDim>() = paper.B;
}

// The actuator model: the thrust input drives the state c, which drives the velocity as u_c did.
void actuatorDynamics(const TangentSystem& paper, double tau, Eigen::Matrix<double, kActuatorDim, kActuatorDim>& A,
                      Eigen::Matrix<double, kActuatorDim, kInputDim>& B) {
  A.setZero();
  B.setZero();
  A.topLeftCorner<kTangentDim, kTangentDim>() = paper.A;
  A.block<kTangentDim, 1>(0, kTangentDim) = paper.B.col(kThrust);
  A(kTangentDim, kTangentDim) = -1.0 / tau;
  B.topRows<kTangentDim>() = paper.B;
  B.block<kTangentDim, 1>(0, kThrust).setZero();
  B(kTangentDim, kThrust) = 1.0 / tau;
}

template <int N>
ExtendedLqrResult solveAugmented(const AugmentedSystem<N>& system, const State& x_lin, const LqrParams& params,
                                 int extra_column) {
  const DiscreteSystem<N, kInputDim> discrete = discretizeZoh<N, kInputDim>(system.A, system.B, params.dt);
  if (!discrete.A.allFinite() || !discrete.B.allFinite()) {
    return failure(SolveStatus::kNumericalFailure, "non-finite discretized system");
  }
  const InputWeight R = params.r_diag.asDiagonal();
  const int max_doublings = params.max_iterations > 0 ? params.max_iterations : kDefaultMaxDoublings;
  const DareSolution<N, kInputDim> dare =
      solveDareDoubling<N, kInputDim>(discrete.A, discrete.B, system.Q, R, params.tolerance, max_doublings);
  if (dare.status != SolveStatus::kOk) return failure(dare.status, "Riccati solver failed", dare.doublings);
  const CertifiedGain<N, kInputDim> gain = certifiedRiccatiGain<N, kInputDim>(discrete.A, discrete.B, system.Q, R, dare.X);
  if (!gain.finite) return failure(SolveStatus::kNumericalFailure, "non-finite gain", dare.doublings);
  if (!gain.stable) return failure(SolveStatus::kNumericalFailure, "closed loop not proven stable", dare.doublings);
  ExtendedLqrResult result;
  result.lqr.status = SolveStatus::kOk;
  result.lqr.residual = gain.relative_residual;
  result.lqr.iterations = dare.doublings;
  result.lqr.P = dare.X.template topLeftCorner<kTangentDim, kTangentDim>();
  result.lqr.K = liftTangentGain(gain.K.template leftCols<kTangentDim>(), tangentBasis(orientation(x_lin)));
  result.K_aug.middleCols(extra_column, N - kTangentDim) = gain.K.template rightCols<N - kTangentDim>();
  return result;
}

template <int N>
double spectralRadius(const Eigen::Matrix<double, N, N>& A, const Eigen::Matrix<double, N, kInputDim>& B, double dt,
                      const Eigen::Matrix<double, kInputDim, N>& K) {
  const DiscreteSystem<N, kInputDim> discrete = discretizeZoh<N, kInputDim>(A, B, dt);
  const Eigen::Matrix<double, N, N> closed = discrete.A + discrete.B * K;
  if (!closed.allFinite()) return kNan;
  Eigen::EigenSolver<Eigen::Matrix<double, N, N>> solver(closed, /*computeEigenvectors=*/false);
  if (solver.info() != Eigen::Success) return kNan;
  return solver.eigenvalues().cwiseAbs().maxCoeff();
}

}  // namespace

AugmentedSystem<kIntegralDim> integralTangentSystem(const State& x_lin, const Input& u_lin, const LqrParams& params) {
  const TangentSystem paper = paperTangentSystem(x_lin, u_lin, params.q_diag, params.rotorDrag());
  AugmentedSystem<kIntegralDim> system;
  integralDynamics(paper, system.A, system.B);
  system.Q.setZero();
  system.Q.topLeftCorner<kTangentDim, kTangentDim>() = paper.Q;
  system.Q.diagonal().tail<3>() = params.q_integral;
  return system;
}

AugmentedSystem<kActuatorDim> actuatorTangentSystem(const State& x_lin, const Input& u_lin, const LqrParams& params) {
  const TangentSystem paper = paperTangentSystem(x_lin, u_lin, params.q_diag, params.rotorDrag());
  AugmentedSystem<kActuatorDim> system;
  actuatorDynamics(paper, params.thrust_time_constant, system.A, system.B);
  system.Q.setZero();
  system.Q.topLeftCorner<kTangentDim, kTangentDim>() = paper.Q;
  system.Q(kTangentDim, kTangentDim) = params.q_thrust;
  return system;
}

ExtendedLqrResult solveLqrForLaw(const State& x_lin, const Input& u_lin, const LqrParams& params,
                                 double thrust_gain) {
  const bool integral = params.law == ControlLaw::kSdlqrIntegral;
  const bool actuator = params.law == ControlLaw::kSdlqrActuator;
  if (!integral && !actuator) {
    ExtendedLqrResult result;
    result.lqr = solveLqr(x_lin, u_lin, params, thrust_gain);
    return result;
  }
  // The preconditions of solveLqr.
  if (!params.valid()) return failure(SolveStatus::kInvalidInput, "invalid LQR parameters");
  if (!x_lin.allFinite()) return failure(SolveStatus::kInvalidInput, "non-finite linearization state");
  if (!u_lin.allFinite()) return failure(SolveStatus::kInvalidInput, "non-finite linearization input");
  const double q_norm = orientation(x_lin).norm();
  if (!(q_norm >= 1e-9)) return failure(SolveStatus::kInvalidInput, "zero quaternion");
  if (params.method != LqrMethod::kTangent) return failure(SolveStatus::kInvalidInput, "extensions need method tangent");
  State x = x_lin;
  orientation(x) /= q_norm;
  return integral ? solveAugmented<kIntegralDim>(integralTangentSystem(x, u_lin, params), x, params, kAugIntegral)
                  : solveAugmented<kActuatorDim>(actuatorTangentSystem(x, u_lin, params), x, params, kAugThrust);
}

double extendedClosedLoopSpectralRadius(ControlLaw law, const State& x_lin, const Input& u_lin, double dt, double tau,
                                        const GainMatrix& K, const Mat4& K_aug, const RotorDrag& drag) {
  if (!K.allFinite() || !K_aug.allFinite() || !x_lin.allFinite() || !u_lin.allFinite() || !(dt > 0.0) ||
      orientation(x_lin).norm() < 1e-9) {
    return kNan;
  }
  State x = x_lin;
  orientation(x).normalize();
  const TangentBasis E = tangentBasis(orientation(x));
  const TangentSystem paper = paperTangentSystem(x, u_lin, State::Zero(), drag);
  const TangentGainMatrix K_r = K * E;
  if (law == ControlLaw::kSdlqrIntegral) {
    Eigen::Matrix<double, kIntegralDim, kIntegralDim> A;
    Eigen::Matrix<double, kIntegralDim, kInputDim> B;
    integralDynamics(paper, A, B);
    Eigen::Matrix<double, kInputDim, kIntegralDim> K_full;
    K_full << K_r, K_aug.middleCols<3>(kAugIntegral);
    return spectralRadius<kIntegralDim>(A, B, dt, K_full);
  }
  if (law == ControlLaw::kSdlqrActuator) {
    if (!(tau > 0.0)) return kNan;
    Eigen::Matrix<double, kActuatorDim, kActuatorDim> A;
    Eigen::Matrix<double, kActuatorDim, kInputDim> B;
    actuatorDynamics(paper, tau, A, B);
    Eigen::Matrix<double, kInputDim, kActuatorDim> K_full;
    K_full << K_r, K_aug.col(kAugThrust);
    return spectralRadius<kActuatorDim>(A, B, dt, K_full);
  }
  return kNan;
}

}  // namespace sdlqr
