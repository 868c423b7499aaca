#include "sdlqr/math/riccati.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "certificate_kernel.hpp"
#include "sda_kernel.hpp"
#include "small_kernels.hpp"

namespace sdlqr {

namespace {

template <int R, int C>
using Mat = Eigen::Matrix<double, R, C>;

// Solves S Z = B in place (B becomes Z) for a symmetric positive definite M x M matrix S, by a
// Cholesky factorization written out for these small sizes: Eigen's LLT::solve with a matrix
// right-hand side takes its blocked triangular-solve path (operand packing), which cost about
// 0.1 us per call here. False, B untouched, when S is not positive definite (or not finite).
template <int M, int C>
bool choleskySolveInPlace(const Mat<M, M>& S, Mat<M, C>& B) {
  double l[M][M], inverse_diagonal[M];
  for (int j = 0; j < M; ++j) {
    double diagonal = S(j, j);
    for (int k = 0; k < j; ++k) diagonal -= l[j][k] * l[j][k];
    if (!(diagonal > 0.0) || !std::isfinite(diagonal)) return false;
    l[j][j] = std::sqrt(diagonal);
    inverse_diagonal[j] = 1.0 / l[j][j];
    for (int i = j + 1; i < M; ++i) {
      double value = S(i, j);
      for (int k = 0; k < j; ++k) value -= l[i][k] * l[j][k];
      l[i][j] = value * inverse_diagonal[j];
    }
  }
  for (int c = 0; c < C; ++c) {  // L y = b, then L^T z = y
    double z[M];
    for (int i = 0; i < M; ++i) {
      double value = B(i, c);
      for (int k = 0; k < i; ++k) value -= l[i][k] * z[k];
      z[i] = value * inverse_diagonal[i];
    }
    for (int i = M - 1; i >= 0; --i) {
      double value = z[i];
      for (int k = i + 1; k < M; ++k) value -= l[k][i] * z[k];
      z[i] = value * inverse_diagonal[i];
    }
    for (int i = 0; i < M; ++i) B(i, c) = z[i];
  }
  return true;
}

template <int N>
void symmetrize(Mat<N, N>& X) {
  for (int j = 0; j < N; ++j) {
    for (int i = 0; i < j; ++i) {
      const double mean = 0.5 * (X(i, j) + X(j, i));
      X(i, j) = mean;
      X(j, i) = mean;
    }
  }
}

}  // namespace

template <int N, int M>
DareSolution<N, M> solveDareDoubling(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<N, N>& Q, const Mat<M, M>& R,
                                     double tolerance, int max_doublings) {
  DareSolution<N, M> solution;
  if (!A.allFinite() || !B.allFinite() || !Q.allFinite() || !R.allFinite()) return solution;
  // G_0 = B R^-1 B^T (lazy products: Eigen's blocked paths cost more than they save at this size).
  Mat<M, N> R_inverse_Bt = B.transpose();
  if (!choleskySolveInPlace<M, N>(R, R_inverse_Bt)) return solution;
  const Mat<N, N> G0 = B.lazyProduct(R_inverse_Bt);

  double Ak[N * N], Gk[N * N], Hk[N * N];  // row-major
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      Ak[i * N + j] = A(i, j);
      Gk[i * N + j] = 0.5 * (G0(i, j) + G0(j, i));
      Hk[i * N + j] = 0.5 * (Q(i, j) + Q(j, i));
    }
  }
  const sda_detail::DoublingOutcome outcome = sda_detail::doublingLoop<N>(Ak, Gk, Hk, tolerance, max_doublings);
  solution.doublings = outcome.doublings;
  solution.last_change = outcome.last_change;
  if (!outcome.finite) {
    solution.status = SolveStatus::kNumericalFailure;
    return solution;
  }
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) solution.X(i, j) = Hk[i * N + j];
  }
  solution.status = outcome.converged ? SolveStatus::kOk : SolveStatus::kNotConverged;
  return solution;
}

template <int N, int M>
bool riccatiGain(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<M, M>& R, const Mat<N, N>& X, Mat<M, N>& K) {
  // Coefficient-based (lazy) products: Eigen's blocked GEMM path costs more than it saves here.
  const Mat<M, N> BtX = B.transpose().lazyProduct(X);
  const Mat<M, M> S = R + BtX.lazyProduct(B);
  Mat<M, N> BtXA = BtX.lazyProduct(A);
  if (!choleskySolveInPlace<M, N>(S, BtXA)) return false;
  K = -BtXA;
  return true;
}

template <int N, int M>
Mat<N, N> dareResidualMatrix(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<N, N>& Q, const Mat<M, M>& R,
                             const Mat<N, N>& X) {
  Mat<M, N> K;
  if (!riccatiGain<N, M>(A, B, R, X, K)) return Mat<N, N>::Constant(std::numeric_limits<double>::quiet_NaN());
  // A^T X A - A^T X B (R + B^T X B)^-1 B^T X A = A^T X (A + B K).
  return A.transpose() * X * (A + B * K) - X + Q;
}

template <int N, int M>
double dareRelativeResidual(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<N, N>& Q, const Mat<M, M>& R,
                            const Mat<N, N>& X) {
  return dareResidualMatrix<N, M>(A, B, Q, R, X).norm() / Q.norm();
}

template <int N>
bool provenSchurStable(const Mat<N, N>& A_cl, const Mat<N, N>& lyapunov) {
  if (!A_cl.allFinite()) return false;
  if (lyapunov.allFinite()) {
    const Eigen::LLT<Mat<N, N>> p_factor(lyapunov);
    if (p_factor.info() == Eigen::Success) {
      const Mat<N, N> decrease = lyapunov - A_cl.transpose() * lyapunov * A_cl;
      const Eigen::LLT<Mat<N, N>> d_factor(decrease);
      if (d_factor.info() == Eigen::Success) return true;
    }
  }
  Mat<N, N> power = A_cl;
  for (int j = 0; j <= 40; ++j) {
    const double norm = power.cwiseAbs().rowwise().sum().maxCoeff();
    if (!std::isfinite(norm)) return false;
    if (norm < 1.0) return true;
    const Mat<N, N> squared = power * power;
    power = squared;
  }
  return false;
}

template <int N, int M>
CertifiedGain<N, M> certifiedRiccatiGain(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<N, N>& Q,
                                         const Mat<M, M>& R, const Mat<N, N>& X) {
  CertifiedGain<N, M> out;
  Mat<M, N> K;
  if (!riccatiGain<N, M>(A, B, R, X, K) || !K.allFinite()) return out;
  const Mat<N, N> A_cl = A + B.lazyProduct(K);
  const sda_detail::LyapunovOutcome check = sda_detail::lyapunovCheck<N>(A.data(), A_cl.data(), X.data(), Q.data());
  out.relative_residual = std::sqrt(check.residual_squared) / Q.norm();
  out.finite = std::isfinite(out.relative_residual);
  if (!out.finite) return out;
  out.K = K;
  out.lyapunov = check.lyapunov;
  out.stable = check.lyapunov ||
               provenSchurStable<N>(A_cl, Mat<N, N>::Constant(std::numeric_limits<double>::quiet_NaN()));
  return out;
}

template <int N, int M>
ValueIterationResult<N, M> riccatiValueIteration(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<N, N>& Q,
                                                 const Mat<M, M>& R, double tolerance, int max_iterations) {
  ValueIterationResult<N, M> result;
  if (!A.allFinite() || !B.allFinite() || !Q.allFinite() || !R.allFinite()) return result;
  if (Eigen::LLT<Mat<M, M>>(R).info() != Eigen::Success) return result;

  Mat<N, N> X = Q;
  symmetrize<N>(X);
  Mat<M, N> K_previous = Mat<M, N>::Zero();
  for (int k = 1; k <= max_iterations; ++k) {
    Mat<M, N> K;
    if (!riccatiGain<N, M>(A, B, R, X, K)) {
      result.status = SolveStatus::kNumericalFailure;
      return result;
    }
    const Mat<N, N> A_cl = A + B * K;
    // Joseph form: symmetric and positive semidefinite by construction, unlike Q + A^T X A_cl.
    Mat<N, N> X_next = Q + K.transpose() * R * K + A_cl.transpose() * X * A_cl;
    symmetrize<N>(X_next);
    X = X_next;
    result.iterations = k;
    if (!X.allFinite() || !K.allFinite()) {
      result.status = SolveStatus::kNumericalFailure;
      return result;
    }
    const double change = (K - K_previous).cwiseAbs().maxCoeff();
    K_previous = K;
    if (k > 1 && change <= tolerance * K.cwiseAbs().maxCoeff()) {
      result.X = X;
      result.K = K;
      result.status = SolveStatus::kOk;
      return result;
    }
  }
  result.X = X;
  result.K = K_previous;
  result.status = SolveStatus::kNotConverged;
  return result;
}

#define SDLQR_INSTANTIATE_RICCATI(N, M)                                                                              \
  template DareSolution<N, M> solveDareDoubling<N, M>(const Mat<N, N>&, const Mat<N, M>&, const Mat<N, N>&,        \
                                                      const Mat<M, M>&, double, int);                              \
  template bool riccatiGain<N, M>(const Mat<N, N>&, const Mat<N, M>&, const Mat<M, M>&, const Mat<N, N>&,          \
                                  Mat<M, N>&);                                                                     \
  template Mat<N, N> dareResidualMatrix<N, M>(const Mat<N, N>&, const Mat<N, M>&, const Mat<N, N>&,                \
                                              const Mat<M, M>&, const Mat<N, N>&);                                 \
  template double dareRelativeResidual<N, M>(const Mat<N, N>&, const Mat<N, M>&, const Mat<N, N>&,                 \
                                             const Mat<M, M>&, const Mat<N, N>&);                                  \
  template ValueIterationResult<N, M> riccatiValueIteration<N, M>(const Mat<N, N>&, const Mat<N, M>&,              \
                                                                  const Mat<N, N>&, const Mat<M, M>&, double, int); \
  template bool provenSchurStable<N>(const Mat<N, N>&, const Mat<N, N>&);                                        \
  template CertifiedGain<N, M> certifiedRiccatiGain<N, M>(const Mat<N, N>&, const Mat<N, M>&, const Mat<N, N>&,    \
                                                          const Mat<M, M>&, const Mat<N, N>&);

SDLQR_INSTANTIATE_RICCATI(1, 1)
SDLQR_INSTANTIATE_RICCATI(2, 1)
SDLQR_INSTANTIATE_RICCATI(9, 4)
SDLQR_INSTANTIATE_RICCATI(10, 4)
SDLQR_INSTANTIATE_RICCATI(12, 4)

#undef SDLQR_INSTANTIATE_RICCATI

}  // namespace sdlqr
