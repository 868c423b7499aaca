#include "sdlqr/common/riccati.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace sdlqr {

namespace {

template <int R, int C>
using Mat = Eigen::Matrix<double, R, C>;

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
  const Eigen::LLT<Mat<M, M>> r_factor(R);
  if (r_factor.info() != Eigen::Success) return solution;

  // G_0 = B R^-1 B^T = F^T F with F = L^-1 B^T.
  const Mat<M, N> F = r_factor.matrixL().solve(B.transpose());
  Mat<N, N> Ak = A;
  Mat<N, N> Gk = F.transpose() * F;
  Mat<N, N> Hk = Q;
  symmetrize<N>(Hk);

  double previous_change = std::numeric_limits<double>::infinity();
  for (int k = 1; k <= max_doublings; ++k) {
    const Mat<N, N> W = Mat<N, N>::Identity() + Gk * Hk;
    const Eigen::PartialPivLU<Mat<N, N>> w_factor(W);
    const Mat<N, N> WinvA = w_factor.solve(Ak);
    const Mat<N, N> WinvG = w_factor.solve(Gk);
    Mat<N, N> H_next = Hk + Ak.transpose() * (Hk * WinvA);
    Mat<N, N> G_next = Gk + Ak * WinvG * Ak.transpose();
    const Mat<N, N> A_next = Ak * WinvA;
    symmetrize<N>(H_next);
    symmetrize<N>(G_next);

    const double change = (H_next - Hk).norm() / H_next.norm();
    Ak = A_next;
    Gk = G_next;
    Hk = H_next;
    solution.doublings = k;
    solution.last_change = change;
    if (!std::isfinite(change) || !Hk.allFinite()) {
      solution.status = SolveStatus::kNumericalFailure;
      return solution;
    }
    const bool quadratic = k >= 2 && change < 1e-3 && change < previous_change;
    const double predicted_next = change * change * change / (previous_change * previous_change);
    if (change <= tolerance || (quadratic && predicted_next <= tolerance)) {
      solution.X = Hk;
      solution.status = SolveStatus::kOk;
      return solution;
    }
    previous_change = change;
  }
  solution.X = Hk;
  solution.status = SolveStatus::kNotConverged;
  return solution;
}

template <int N, int M>
bool riccatiGain(const Mat<N, N>& A, const Mat<N, M>& B, const Mat<M, M>& R, const Mat<N, N>& X, Mat<M, N>& K) {
  const Mat<M, N> BtX = B.transpose() * X;
  const Eigen::LLT<Mat<M, M>> factor(R + BtX * B);
  if (factor.info() != Eigen::Success) return false;
  K = -factor.solve(BtX * A);
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
  template bool provenSchurStable<N>(const Mat<N, N>&, const Mat<N, N>&);

SDLQR_INSTANTIATE_RICCATI(1, 1)
SDLQR_INSTANTIATE_RICCATI(2, 1)
SDLQR_INSTANTIATE_RICCATI(9, 4)
SDLQR_INSTANTIATE_RICCATI(10, 4)

#undef SDLQR_INSTANTIATE_RICCATI

}  // namespace sdlqr
