#pragma once
// Internal to common/math/src (riccati.cpp): the residual and the Lyapunov certificate of a DARE
// candidate X with closed loop A_cl (certifiedRiccatiGain), on L-lane vectors (vector_kernels.hpp):
//
//   residual   R = A^T (X A_cl) - X + Q               (its squared Frobenius norm)
//   decrease   E = X - A_cl^T (X A_cl)                 (lower triangle only: it is symmetric)
//   lyapunov   X and E both positive definite          (then rho(A_cl) < 1)
//
// Positive definiteness is decided by symmetric Gaussian elimination without pivoting (the LDL^T
// form of Cholesky): a symmetric matrix is positive definite exactly when every pivot is positive.
// Row operations run on whole vectors, unlike the scalar inner products of a textbook Cholesky.
// Both tests read only the lower triangle of their matrix (the upper one is mirrored from it).

#include <cmath>

#include "small_kernels.hpp"
#include "vector_kernels.hpp"

namespace sdlqr::sda_detail {

// True when the symmetric N x N matrix m (stride S, lower triangle mirrored onto the upper one)
// is positive definite; m is overwritten.
template <int L, int N, int S>
SDLQR_SDA_INLINE bool positiveDefiniteByElimination(double* m) {
  using Vec = typename Lanes<L>::Vec;
  constexpr int NS = S / L;
  for (int j = 0; j < N; ++j) {
    const double pivot = m[j * S + j];
    if (!(pivot > 0.0) || !std::isfinite(pivot)) return false;
    const double inverse = 1.0 / pivot;
    const double* pivot_row = m + j * S;
    // Columns left of j are never read again: start at the vector that holds column j.
    for (int i = j + 1; i < N; ++i) {
      double* row = m + i * S;
      const double factor = row[j] * inverse;
      for (int v = j / L; v < NS; ++v) at<L>(row + L * v) -= factor * Vec(at<L>(pivot_row + L * v));
    }
  }
  return true;
}

// Inputs column-major N x N (Eigen's layout: m(i, j) = m[j * N + i]).
template <int N, int L, int kAccumulators>
SDLQR_SDA_INLINE LyapunovOutcome lyapunovVectorBody(const double* A_in, const double* A_cl_in, const double* X_in,
                                                    const double* Q_in) {
  using Vec = typename Lanes<L>::Vec;
  using Mask = typename Lanes<L>::Mask;
  constexpr int S = roundUp(N, L);
  constexpr int NS = S / L;
  // Padding columns are zeroed where a product reads them as a right operand or the elimination
  // sweeps over them; A is only read as a left operand (real columns).
  alignas(64) double A[N * S], A_cl[N * S], X[N * S], X_A_cl[N * S], residual[N * S], quadratic[N * S];
  alignas(64) double X_lower[N * S], decrease[N * S];
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      A[i * S + j] = A_in[j * N + i];
      A_cl[i * S + j] = A_cl_in[j * N + i];
      X[i * S + j] = X_in[j * N + i];
      X_lower[i * S + j] = j <= i ? X_in[j * N + i] : X_in[i * N + j];
      residual[i * S + j] = Q_in[j * N + i] - X_in[j * N + i];
    }
    for (int j = N; j < S; ++j) {
      A_cl[i * S + j] = X[i * S + j] = X_lower[i * S + j] = residual[i * S + j] = 0.0;
    }
  }
  for (int i = 0; i < N * S; ++i) decrease[i] = 0.0;
  product<L, kAccumulators, N, 0, N, NS, false, false, S, S, S>(X, A_cl, X_A_cl);
  product<L, kAccumulators, N, 0, N, NS, true, true, S, S, S>(A, X_A_cl, residual);
  lowerProduct<L, kAccumulators, N, 0, true, S, S, S>(A_cl, X_A_cl, quadratic);

  LyapunovOutcome outcome;
  Mask lane_index = {};
  for (int j = 0; j < L; ++j) lane_index[j] = j;
  Vec sum{};
  for (int i = 0; i < N; ++i) {
    for (int v = 0; v < NS; ++v) {
      const Vec r = lane_index + L * v < N ? Vec(at<L>(residual + i * S + L * v)) : Vec{};
      sum += r * r;
    }
  }
  for (int j = 0; j < L; ++j) outcome.residual_squared += sum[j];

  for (int i = 0; i < N; ++i) {
    for (int j = 0; j <= i; ++j) {
      const double value = X_lower[i * S + j] - quadratic[i * S + j];
      decrease[i * S + j] = value;
      decrease[j * S + i] = value;
    }
  }
  outcome.lyapunov =
      positiveDefiniteByElimination<L, N, S>(X_lower) && positiveDefiniteByElimination<L, N, S>(decrease);
  return outcome;
}

// Compiled per instruction set (kernel_isa.hpp); accumulator budgets as in sda_kernel.hpp.
template <int N>
SDLQR_AVX512_TARGET LyapunovOutcome lyapunovAvx512(const double* A, const double* A_cl, const double* X,
                                                   const double* Q) {
  return lyapunovVectorBody<N, 8, 24>(A, A_cl, X, Q);
}

template <int N>
SDLQR_AVX2_TARGET LyapunovOutcome lyapunovAvx2(const double* A, const double* A_cl, const double* X,
                                               const double* Q) {
  return lyapunovVectorBody<N, 4, 9>(A, A_cl, X, Q);
}

// The certificate of column-major N x N inputs on the instruction set of activeKernelIsa();
// the baseline keeps the scalar-Cholesky version of small_kernels.hpp.
template <int N>
LyapunovOutcome lyapunovCheck(const double* A, const double* A_cl, const double* X, const double* Q) {
  switch (activeKernelIsa()) {
    case KernelIsa::kAvx512: return lyapunovAvx512<N>(A, A_cl, X, Q);
    case KernelIsa::kAvx2Fma: return lyapunovAvx2<N>(A, A_cl, X, Q);
    default: break;
  }
  Block<N, N> a{}, a_cl{}, x{}, q{};
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      a(i, j) = A[j * N + i];
      a_cl(i, j) = A_cl[j * N + i];
      x(i, j) = X[j * N + i];
      q(i, j) = Q[j * N + i];
    }
  }
  return lyapunovBaseline<N>(a, a_cl, x, q);
}

}  // namespace sdlqr::sda_detail
