#include "sdlqr/math/lqr.hpp"

#include <cmath>

#include "sdlqr/math/discretize.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/math/riccati.hpp"

namespace sdlqr {

namespace {

using QuatTangent = Eigen::Matrix<double, 4, 3>;

constexpr int kDefaultMaxDoublings = 64;
constexpr int kDefaultMaxIterations = 100000;
constexpr double kMinQuaternionNorm = 1e-9;

QuatTangent quaternionTangent(const Quat& q_unit) { return quat::leftMatrix(q_unit).rightCols<3>(); }

LqrResult failure(SolveStatus status, const char* reason, int iterations = 0) {
  LqrResult result;
  result.status = status;
  result.reason = reason;
  result.iterations = iterations;
  return result;
}

const char* dareFailureReason(SolveStatus status) {
  switch (status) {
    case SolveStatus::kNotConverged: return "Riccati solver did not converge within max_iterations";
    case SolveStatus::kNumericalFailure: return "non-finite value in the Riccati solver";
    default: return "Riccati solver rejected its input";
  }
}

LqrResult solveTangent(const State& x, const Input& u, const LqrParams& params, double thrust_gain) {
  const TangentBasis E = tangentBasis(orientation(x));
  const TangentSystem system = projectToTangent(linearize(x, u, thrust_gain, params.rotorDrag()), E, params.q_diag);
  const DiscreteSystem<kTangentDim, kInputDim> discrete = discretizeZoh<kTangentDim, kInputDim>(system.A, system.B, params.dt);
  if (!discrete.A.allFinite() || !discrete.B.allFinite()) {
    return failure(SolveStatus::kNumericalFailure, "non-finite discretized system");
  }
  const InputWeight R = params.r_diag.asDiagonal();
  const int max_doublings = params.max_iterations > 0 ? params.max_iterations : kDefaultMaxDoublings;
  const DareSolution<kTangentDim, kInputDim> dare = solveDareDoubling<kTangentDim, kInputDim>(
      discrete.A, discrete.B, system.Q, R, params.tolerance, max_doublings);
  if (dare.status != SolveStatus::kOk) return failure(dare.status, dareFailureReason(dare.status), dare.doublings);

  const CertifiedGain<kTangentDim, kInputDim> gain =
      certifiedRiccatiGain<kTangentDim, kInputDim>(discrete.A, discrete.B, system.Q, R, dare.X);
  if (!gain.finite) return failure(SolveStatus::kNumericalFailure, "non-finite gain", dare.doublings);
  if (!gain.stable) return failure(SolveStatus::kNumericalFailure, "closed loop not proven stable", dare.doublings);
  LqrResult result;
  result.residual = gain.relative_residual;
  result.status = SolveStatus::kOk;
  result.K = liftTangentGain(gain.K, E);
  result.P = dare.X;
  result.iterations = dare.doublings;
  return result;
}

LqrResult solveIterative(const State& x, const Input& u, const LqrParams& params, double thrust_gain) {
  const Linearization linearization = linearize(x, u, thrust_gain, params.rotorDrag());
  const DiscreteSystem<kStateDim, kInputDim> discrete =
      discretizeZoh<kStateDim, kInputDim>(linearization.A, linearization.B, params.dt);
  if (!discrete.A.allFinite() || !discrete.B.allFinite()) {
    return failure(SolveStatus::kNumericalFailure, "non-finite discretized system");
  }
  const StateMatrix Q = params.q_diag.asDiagonal();
  const InputWeight R = params.r_diag.asDiagonal();
  const int max_iterations = params.max_iterations > 0 ? params.max_iterations : kDefaultMaxIterations;
  const ValueIterationResult<kStateDim, kInputDim> solution = riccatiValueIteration<kStateDim, kInputDim>(
      discrete.A, discrete.B, Q, R, params.tolerance, max_iterations);
  if (solution.status != SolveStatus::kOk) {
    return failure(solution.status, dareFailureReason(solution.status), solution.iterations);
  }

  // Stability and residual are judged on the tangent space: along n the closed loop keeps its
  // eigenvalue 1 (K n need not vanish, but Ad n = n and the norm of a unit quaternion is fixed).
  const TangentBasis E = tangentBasis(orientation(x));
  const TangentMatrix closed_loop = E.transpose() * (discrete.A + discrete.B * solution.K) * E;
  const TangentMatrix P_tangent = E.transpose() * solution.X * E;
  if (!provenSchurStable<kTangentDim>(closed_loop, P_tangent)) {
    return failure(SolveStatus::kNumericalFailure, "closed loop not proven stable", solution.iterations);
  }
  const StateMatrix residual = dareResidualMatrix<kStateDim, kInputDim>(discrete.A, discrete.B, Q, R, solution.X);
  LqrResult result;
  result.residual = (E.transpose() * residual * E).norm() / (E.transpose() * Q * E).norm();
  if (!std::isfinite(result.residual)) {
    return failure(SolveStatus::kNumericalFailure, "non-finite Riccati residual", solution.iterations);
  }
  result.status = SolveStatus::kOk;
  result.K = solution.K;
  result.P = P_tangent;
  result.iterations = solution.iterations;
  return result;
}

}  // namespace

TangentBasis tangentBasis(const Quat& q_unit) {
  TangentBasis E = TangentBasis::Zero();
  E.block<3, 3>(kPos, kTanPos).setIdentity();
  E.block<4, 3>(kQuat, kTanRot) = quaternionTangent(q_unit);
  E.block<3, 3>(kVel, kTanVel).setIdentity();
  return E;
}

TangentSystem projectToTangent(const Linearization& linearization, const TangentBasis& E, const State& q_diag) {
  // E is block diagonal, so each block of E^T A E is one small product.
  const QuatTangent G = E.block<4, 3>(kQuat, kTanRot);
  const StateMatrix& A = linearization.A;
  const InputMatrix& B = linearization.B;
  TangentSystem system;
  system.A.block<3, 3>(kTanPos, kTanPos) = A.block<3, 3>(kPos, kPos);
  system.A.block<3, 3>(kTanPos, kTanRot) = A.block<3, 4>(kPos, kQuat) * G;
  system.A.block<3, 3>(kTanPos, kTanVel) = A.block<3, 3>(kPos, kVel);
  system.A.block<3, 3>(kTanRot, kTanPos) = G.transpose() * A.block<4, 3>(kQuat, kPos);
  system.A.block<3, 3>(kTanRot, kTanRot) = G.transpose() * A.block<4, 4>(kQuat, kQuat) * G;
  system.A.block<3, 3>(kTanRot, kTanVel) = G.transpose() * A.block<4, 3>(kQuat, kVel);
  system.A.block<3, 3>(kTanVel, kTanPos) = A.block<3, 3>(kVel, kPos);
  system.A.block<3, 3>(kTanVel, kTanRot) = A.block<3, 4>(kVel, kQuat) * G;
  system.A.block<3, 3>(kTanVel, kTanVel) = A.block<3, 3>(kVel, kVel);

  system.B.block<3, 4>(kTanPos, 0) = B.block<3, 4>(kPos, 0);
  system.B.block<3, 4>(kTanRot, 0) = G.transpose() * B.block<4, 4>(kQuat, 0);
  system.B.block<3, 4>(kTanVel, 0) = B.block<3, 4>(kVel, 0);

  system.Q.setZero();
  system.Q.diagonal().segment<3>(kTanPos) = q_diag.segment<3>(kPos);
  system.Q.block<3, 3>(kTanRot, kTanRot) = G.transpose() * q_diag.segment<4>(kQuat).asDiagonal() * G;
  system.Q.diagonal().segment<3>(kTanVel) = q_diag.segment<3>(kVel);
  return system;
}

GainMatrix liftTangentGain(const TangentGainMatrix& K_r, const TangentBasis& E) {
  GainMatrix K;
  K.middleCols<3>(kPos) = K_r.middleCols<3>(kTanPos);
  K.middleCols<4>(kQuat) = K_r.middleCols<3>(kTanRot) * E.block<4, 3>(kQuat, kTanRot).transpose();
  K.middleCols<3>(kVel) = K_r.middleCols<3>(kTanVel);
  return K;
}

LqrResult solveLqr(const State& x_lin, const Input& u_lin, const LqrParams& params, double thrust_gain) {
  if (!params.valid()) return failure(SolveStatus::kInvalidInput, "invalid LQR parameters");
  if (!(thrust_gain > 0.0 && std::isfinite(thrust_gain))) return failure(SolveStatus::kInvalidInput, "thrust gain not > 0");
  if (!x_lin.allFinite()) return failure(SolveStatus::kInvalidInput, "non-finite linearization state");
  if (!u_lin.allFinite()) return failure(SolveStatus::kInvalidInput, "non-finite linearization input");
  const double q_norm = orientation(x_lin).norm();
  if (!(q_norm >= kMinQuaternionNorm)) return failure(SolveStatus::kInvalidInput, "zero quaternion");

  State x = x_lin;
  orientation(x) /= q_norm;
  return params.method == LqrMethod::kTangent ? solveTangent(x, u_lin, params, thrust_gain)
                                              : solveIterative(x, u_lin, params, thrust_gain);
}

}  // namespace sdlqr
