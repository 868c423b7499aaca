#pragma once
// The state-dependent LQR gain (paper §II-C, II-D): linearize the model at (x_lin, u_lin),
// discretize with a zero-order hold at dt, solve the discrete algebraic Riccati equation
//
//   P = Ad^T P Ad - Ad^T P Bd (R + Bd^T P Bd)^-1 Bd^T P Ad + Q
//
// and return the paper's 4 x 10 gain of eq. (15), u = u0 + K (x - x0), K = -(R + Bd^T P Bd)^-1 Bd^T P Ad
// (the NEGATIVE of the textbook gain).
//
// Why a tangent space: the quaternion norm direction n = [0, q, 0] is in the null space of A
// (A n = 0, Ad n = n), so the 10-state system has an eigenvalue 1 that no input damps; a textbook
// DARE of the 10-state system is ill-posed (no stabilizing solution at zero body rate). The
// 9-state system z on the orthonormal basis E(q) = blockdiag(I3, G(q), I3), G(q) the last three
// columns of Q^x(q) (orthogonal to q), is exact: x = E z + n s with
//   z_dot = Ar z + Br u,  Ar = E^T A E, Br = E^T B,
// because s never feeds back (A n = 0) and E^T B carries all of B (B has no n component).
// Its cost is Qr = E^T Q E. The 9-state gain K_r maps back as K = K_r E^T, so K n = 0.
//
// Hemisphere: G(-q) = -G(q), so the quaternion columns of K(-q) are those of K(q) negated and
// every other column is equal. K (x - x0) is therefore the same for (q0, K(q0)) and (-q0, K(-q0))
// as long as x - x0 is formed with q in the hemisphere of the quaternion K was built at. A
// controller that instead flips q0 into the hemisphere of the measured q must negate K's
// quaternion columns whenever q . q_lin < 0.

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr {

using TangentBasis = Eigen::Matrix<double, kStateDim, kTangentDim>;

struct LqrResult {
  SolveStatus status = SolveStatus::kInvalidInput;
  GainMatrix K = GainMatrix::Zero();  // finite always; zero unless status == kOk
  // Doublings (tangent) or Riccati iterations (iterative) performed.
  int iterations = 0;
  // ||residual||_F / ||Qr||_F on the 9-state tangent system. Tangent method: the DARE residual of
  // its own P. Iterative method: E^T (F(P) - P) E of the 10-state Riccati map F at its last P,
  // i.e. the tangent part of the 10-state DARE residual (the norm direction of P grows by
  // q^T Q q per iteration where it is uncontrollable, without affecting K). 0 when not computed.
  double residual = 0.0;
  // Tangent-space Riccati solution (9 x 9); for the iterative method E^T P10 E.
  TangentMatrix P = TangentMatrix::Zero();
  const char* reason = "";  // short static text, empty when status == kOk
};

// Linearizes at (x_lin, u_lin), discretizes at params.dt and solves with params.method:
//  - LqrMethod::kTangent: SDA on the 9-state tangent system (at most max_iterations doublings,
//    default 64), K = K_r E^T.
//  - LqrMethod::kIterative: value iteration on the full 10-state system from P = Q until K's
//    relative change <= tolerance (at most max_iterations, default 100000).
// Preconditions checked, each giving kInvalidInput with K zero: params.valid(); x_lin and u_lin
// finite; ||q|| >= 1e-9 (the quaternion is then normalized, so a scaled q gives the same K).
// kNotConverged: iteration limit reached. kNumericalFailure: a non-finite intermediate, or K
// whose tangent closed loop Ad_r + Bd_r K_r is not proven Schur stable. kOk guarantees a finite K
// and a proven-stable tangent closed loop. No heap allocation.
// thrust_gain: the model's (model.hpp linearize); 1 is the paper's.
LqrResult solveLqr(const State& x_lin, const Input& u_lin, const LqrParams& params, double thrust_gain = 1.0);

// --- pieces, public for tests and benchmarks ---

// E(q) = blockdiag(I3, G(q), I3), q a unit quaternion: orthonormal columns, E^T [0, q, 0] = 0.
TangentBasis tangentBasis(const Quat& q_unit);

struct TangentSystem {
  TangentMatrix A;         // E^T A E
  TangentInputMatrix B;    // E^T B
  TangentMatrix Q;         // E^T diag(q_diag) E
};
TangentSystem projectToTangent(const Linearization& linearization, const TangentBasis& E, const State& q_diag);

// K = K_r E^T.
GainMatrix liftTangentGain(const TangentGainMatrix& K_r, const TangentBasis& E);

}  // namespace sdlqr
