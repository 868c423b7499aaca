#pragma once
// Discrete-time algebraic Riccati equation (DARE) solvers on fixed-size matrices.
//
//   X = A^T X A - A^T X B (R + B^T X B)^-1 B^T X A + Q                         (DARE)
//
// A: N x N, B: N x M, Q: N x N symmetric positive semidefinite, R: M x M symmetric positive
// definite. The stabilizing solution exists and is unique when (A, B) is stabilizable and
// (Q^1/2, A) has no unobservable mode on the unit circle. Gains follow the paper's eq. (15):
// u = u0 + K (x - x0), so K = -(R + B^T X B)^-1 B^T X A is the NEGATIVE of the textbook gain.
//
// Everything is fixed-size and allocation-free. Instantiated in riccati.cpp for (N, M) =
// (9, 4) tangent system, (10, 4) full system and actuator extension, (12, 4) integral extension, (1, 1) and (2, 1) analytic test cases.

#include <Eigen/Core>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr {

template <int N, int M>
struct DareSolution {
  Eigen::Matrix<double, N, N> X = Eigen::Matrix<double, N, N>::Zero();
  int doublings = 0;
  SolveStatus status = SolveStatus::kInvalidInput;
  double last_change = 0.0;  // relative Frobenius change of X in the last doubling
};

// Structure-preserving doubling algorithm (SDA; Chu, Fan, Lin, Wang 2004):
//   A_0 = A, G_0 = B R^-1 B^T, H_0 = Q,  W_k = I + G_k H_k,
//   A_k+1 = A_k W_k^-1 A_k,  G_k+1 = G_k + A_k W_k^-1 G_k A_k^T,  H_k+1 = H_k + A_k^T H_k W_k^-1 A_k,
// H_k -> X quadratically: the error of H_k falls like rho^(2^(k+1)), rho the spectral radius of
// the optimal closed loop. Stops when the relative change of H falls below `tolerance` or, once
// the iteration is visibly quadratic, when the change predicted for the next doubling
// (delta_k^3 / delta_k-1^2) does: this saves the doubling that would only confirm convergence.
// Statuses: kOk, kNotConverged (max_doublings reached), kNumericalFailure (non-finite or
// singular W), kInvalidInput (R not positive definite, non-finite data).
template <int N, int M>
DareSolution<N, M> solveDareDoubling(const Eigen::Matrix<double, N, N>& A, const Eigen::Matrix<double, N, M>& B,
                                     const Eigen::Matrix<double, N, N>& Q, const Eigen::Matrix<double, M, M>& R,
                                     double tolerance, int max_doublings);

// K = -(R + B^T X B)^-1 B^T X A. Returns false (K untouched) when R + B^T X B is not positive definite.
template <int N, int M>
bool riccatiGain(const Eigen::Matrix<double, N, N>& A, const Eigen::Matrix<double, N, M>& B,
                 const Eigen::Matrix<double, M, M>& R, const Eigen::Matrix<double, N, N>& X,
                 Eigen::Matrix<double, M, N>& K);

// The DARE residual matrix A^T X A - X - A^T X B (R + B^T X B)^-1 B^T X A + Q (NaN when the
// inner matrix is not positive definite).
template <int N, int M>
Eigen::Matrix<double, N, N> dareResidualMatrix(const Eigen::Matrix<double, N, N>& A,
                                               const Eigen::Matrix<double, N, M>& B,
                                               const Eigen::Matrix<double, N, N>& Q,
                                               const Eigen::Matrix<double, M, M>& R,
                                               const Eigen::Matrix<double, N, N>& X);

// ||dareResidualMatrix||_F / ||Q||_F.
template <int N, int M>
double dareRelativeResidual(const Eigen::Matrix<double, N, N>& A, const Eigen::Matrix<double, N, M>& B,
                            const Eigen::Matrix<double, N, N>& Q, const Eigen::Matrix<double, M, M>& R,
                            const Eigen::Matrix<double, N, N>& X);

// True only when the spectral radius of A_cl is proven < 1: either `lyapunov` and
// lyapunov - A_cl^T lyapunov A_cl are both positive definite (for a DARE solution X this is
// Q + K^T R K, so the check costs two 9x9 Cholesky factorizations), or ||A_cl^(2^j)||_inf < 1 for
// some j <= 40 (rho^(2^j) <= ||A_cl^(2^j)||). False for a non-finite A_cl.
template <int N>
bool provenSchurStable(const Eigen::Matrix<double, N, N>& A_cl, const Eigen::Matrix<double, N, N>& lyapunov);

template <int N, int M>
struct CertifiedGain {
  Eigen::Matrix<double, M, N> K = Eigen::Matrix<double, M, N>::Zero();
  double relative_residual = 0.0;  // as dareRelativeResidual
  bool finite = false;             // K and the residual are finite
  bool stable = false;             // as provenSchurStable(A + B K, X)
  bool lyapunov = false;           // stable proven by the Lyapunov test (not by powers of A + B K)
};

// riccatiGain, dareRelativeResidual and provenSchurStable(A + B K, X) in one pass that shares
// their products (X (A + B K) serves both the residual and the Lyapunov decrease).
template <int N, int M>
CertifiedGain<N, M> certifiedRiccatiGain(const Eigen::Matrix<double, N, N>& A, const Eigen::Matrix<double, N, M>& B,
                                         const Eigen::Matrix<double, N, N>& Q, const Eigen::Matrix<double, M, M>& R,
                                         const Eigen::Matrix<double, N, N>& X);

template <int N, int M>
struct ValueIterationResult {
  Eigen::Matrix<double, N, N> X = Eigen::Matrix<double, N, N>::Zero();
  Eigen::Matrix<double, M, N> K = Eigen::Matrix<double, M, N>::Zero();
  int iterations = 0;
  SolveStatus status = SolveStatus::kInvalidInput;
};

// Riccati value iteration (the paper's dynamic-programming solve, ref. [12]): X_0 = Q,
//   K_k = -(R + B^T X_k B)^-1 B^T X_k A,  X_k+1 = Q + K_k^T R K_k + (A + B K_k)^T X_k (A + B K_k),
// until max|K_k - K_k-1| <= tolerance * max|K_k|. Converges linearly with rate about rho^2, so the
// remaining error of K is about the last change / (1 - rho^2). K converges even when X does
// not, e.g. along an uncontrollable, undamped direction that the gain never sees.
template <int N, int M>
ValueIterationResult<N, M> riccatiValueIteration(const Eigen::Matrix<double, N, N>& A,
                                                 const Eigen::Matrix<double, N, M>& B,
                                                 const Eigen::Matrix<double, N, N>& Q,
                                                 const Eigen::Matrix<double, M, M>& R, double tolerance,
                                                 int max_iterations);

}  // namespace sdlqr
