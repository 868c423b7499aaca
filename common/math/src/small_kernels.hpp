#pragma once
// Internal to common/math/src (riccati.cpp, discretize.cpp): small dense kernels and the
// structure-preserving doubling loop on padded row-major arrays.
// Eigen's fixed 9x9 products leave a scalar tail in every column (9 is no multiple of the SIMD
// width); rows padded to a multiple of 4 doubles let every inner loop run on whole vectors. The
// padding columns hold "don't care" values that never reach a real entry: a product reads
// only the real columns of its left operand.

#include <cmath>
#include <cstring>

#include "sdlqr/math/kernel_isa.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <xmmintrin.h>
#define SDLQR_SMALL_KERNELS_X86 1
#define SDLQR_AVX2_TARGET __attribute__((target("avx2,fma")))
#define SDLQR_AVX512_TARGET __attribute__((target("avx512f,avx512vl,avx512dq,avx2,fma")))
#else
#define SDLQR_AVX2_TARGET
#define SDLQR_AVX512_TARGET
#endif

#define SDLQR_SDA_INLINE inline __attribute__((always_inline))

namespace sdlqr::sda_detail {

constexpr int padded(int n) { return (n + 3) / 4 * 4; }

// R x C real entries, row-major with row stride S >= C.
template <int R, int C, int S = padded(C)>
struct alignas(64) Block {
  double v[R * S];
  double& operator()(int i, int j) { return v[i * S + j]; }
  double operator()(int i, int j) const { return v[i * S + j]; }
  double* row(int i) { return v + i * S; }
  const double* row(int i) const { return v + i * S; }
};

// out (+)= a * b (or a^T * b); the inner loop spans the full padded width W of b's rows. Rows are
// taken RB at a time so that RB * W / 4 independent accumulator chains hide the FMA latency.
template <int N, int W, bool kTransposeA, bool kAccumulate, int SA, int SB, int SO>
SDLQR_SDA_INLINE void multiply(const double* __restrict a, const double* __restrict b, double* __restrict out) {
  constexpr int RB = N % 3 == 0 ? 3 : N % 2 == 0 ? 2 : 1;
  for (int i0 = 0; i0 < N; i0 += RB) {
    double accumulator[RB][W];
    for (int r = 0; r < RB; ++r) {
      for (int j = 0; j < W; ++j) accumulator[r][j] = kAccumulate ? out[(i0 + r) * SO + j] : 0.0;
    }
    for (int k = 0; k < N; ++k) {
      const double* b_row = b + k * SB;
      for (int r = 0; r < RB; ++r) {
        const double factor = kTransposeA ? a[k * SA + i0 + r] : a[(i0 + r) * SA + k];
        for (int j = 0; j < W; ++j) accumulator[r][j] += factor * b_row[j];
      }
    }
    for (int r = 0; r < RB; ++r) {
      for (int j = 0; j < W; ++j) out[(i0 + r) * SO + j] = accumulator[r][j];
    }
  }
}

template <int N, int S>
SDLQR_SDA_INLINE void symmetrize(double* m) {
  for (int i = 0; i < N; ++i) {
    for (int j = i + 1; j < N; ++j) {
      const double mean = 0.5 * (m[i * S + j] + m[j * S + i]);
      m[i * S + j] = mean;
      m[j * S + i] = mean;
    }
  }
}

// In-place Gauss-Jordan elimination with partial pivoting of [W | rhs...] (N rows, stride S,
// W in columns 0..N-1): afterwards the columns from P on hold W^-1 rhs. False when a pivot is
// zero or non-finite.
template <int N, int P, int S>
SDLQR_SDA_INLINE bool gaussJordan(double* m) {
  for (int p = 0; p < N; ++p) {
    int pivot_row = p;
    double pivot_abs = std::fabs(m[p * S + p]);
    for (int i = p + 1; i < N; ++i) {
      const double candidate = std::fabs(m[i * S + p]);
      const bool larger = candidate > pivot_abs;
      pivot_abs = larger ? candidate : pivot_abs;
      pivot_row = larger ? i : pivot_row;
    }
    if (!(pivot_abs > 0.0) || !std::isfinite(pivot_abs)) return false;
    // Columns left of p are finished unit columns (zero in rows p and pivot_row): begin at the
    // vector boundary below p.
    const int first = p / 4 * 4;
    if (pivot_row != p) {
      for (int j = first; j < S; ++j) {
        const double t = m[p * S + j];
        m[p * S + j] = m[pivot_row * S + j];
        m[pivot_row * S + j] = t;
      }
    }
    double* __restrict pivot = m + p * S;
    const double inverse = 1.0 / pivot[p];
    for (int j = first; j < S; ++j) pivot[j] *= inverse;
    for (int i = 0; i < N; ++i) {
      if (i == p) continue;
      double* __restrict target = m + i * S;
      const double factor = target[p];
      for (int j = first; j < S; ++j) target[j] -= factor * pivot[j];
    }
  }
  return true;
}

template <int N, int S>
SDLQR_SDA_INLINE double frobeniusDifference(const double* a, const double* b, double& norm_b) {
  double diff = 0.0, norm = 0.0;
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      const double d = a[i * S + j] - b[i * S + j];
      diff += d * d;
      norm += b[i * S + j] * b[i * S + j];
    }
  }
  norm_b = std::sqrt(norm);
  return std::sqrt(diff);
}

// Cholesky test of a symmetric N x N matrix (stride S): true when positive definite.
template <int N, int S>
SDLQR_SDA_INLINE bool positiveDefinite(const double* m) {
  double l[N][N];
  for (int j = 0; j < N; ++j) {
    double diagonal = m[j * S + j];
    for (int k = 0; k < j; ++k) diagonal -= l[j][k] * l[j][k];
    if (!(diagonal > 0.0) || !std::isfinite(diagonal)) return false;
    l[j][j] = std::sqrt(diagonal);
    const double inverse = 1.0 / l[j][j];
    for (int i = j + 1; i < N; ++i) {
      double value = m[i * S + j];
      for (int k = 0; k < j; ++k) value -= l[i][k] * l[j][k];
      l[i][j] = value * inverse;
    }
  }
  return true;
}

// For a DARE candidate X with closed loop A_cl: the squared Frobenius norm of the residual
// A^T X A_cl - X + Q, and whether X and X - A_cl^T X A_cl are both positive definite (Lyapunov).
struct LyapunovOutcome {
  double residual_squared = 0.0;
  bool lyapunov = false;
};

template <int N>
SDLQR_SDA_INLINE LyapunovOutcome lyapunovBody(const Block<N, N>& A, const Block<N, N>& A_cl, const Block<N, N>& X,
                                              const Block<N, N>& Q) {
  constexpr int S = padded(N);
  Block<N, N> X_A_cl, residual, quadratic;
  multiply<N, S, false, false, S, S, S>(X.v, A_cl.v, X_A_cl.v);
  residual = Q;
  for (int i = 0; i < N * S; ++i) residual.v[i] -= X.v[i];
  multiply<N, S, true, true, S, S, S>(A.v, X_A_cl.v, residual.v);
  multiply<N, S, true, false, S, S, S>(A_cl.v, X_A_cl.v, quadratic.v);
  LyapunovOutcome outcome;
  Block<N, N> decrease;  // X - A_cl^T X A_cl, symmetrized; the Cholesky test reads the lower half
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) outcome.residual_squared += residual(i, j) * residual(i, j);
    for (int j = 0; j <= i; ++j) decrease(i, j) = X(i, j) - 0.5 * (quadratic(i, j) + quadratic(j, i));
  }
  outcome.lyapunov = positiveDefinite<N, S>(X.v) && positiveDefinite<N, S>(decrease.v);
  return outcome;
}

template <int N>
LyapunovOutcome lyapunovBaseline(const Block<N, N>& A, const Block<N, N>& A_cl, const Block<N, N>& X,
                                 const Block<N, N>& Q) {
  return lyapunovBody<N>(A, A_cl, X, Q);
}

struct DoublingOutcome {
  int doublings = 0;
  double last_change = 0.0;
  bool finite = true;
  bool converged = false;
};

// Records doubling k's relative change in `outcome`; true when the loop stops there, converged or
// not finite. Quadratic regime: the next change is about change^3 / previous^2 (riccati.hpp), so a
// prediction within the tolerance stops one doubling early.
SDLQR_SDA_INLINE bool doublingStops(int k, double change, double tolerance, double& previous_change,
                                    DoublingOutcome& outcome) {
  outcome.doublings = k;
  outcome.last_change = change;
  if (!std::isfinite(change)) {
    outcome.finite = false;
    return true;
  }
  const bool quadratic = k >= 2 && change < 1e-3 && change < previous_change;
  const double predicted_next = change * change * change / (previous_change * previous_change);
  if (change <= tolerance || (quadratic && predicted_next <= tolerance)) {
    outcome.converged = true;
    return true;
  }
  previous_change = change;
  return false;
}

// The SDA loop of solveDareDoubling (see riccati.hpp) on N x N blocks; A, G, H are updated in place
// and H holds the solution estimate on return.
template <int N>
SDLQR_SDA_INLINE DoublingOutcome doublingLoopBody(Block<N, N>& A, Block<N, N>& G, Block<N, N>& H, double tolerance, int max_doublings) {
  constexpr int S = padded(N);
  constexpr int SW = 3 * S;  // [W | A | G] side by side, each block on its own vector boundary
  Block<N, SW, SW> augmented;
  Block<N, N> Z, D, T, V;
  DoublingOutcome outcome;
  double previous_change = HUGE_VAL;
  for (int k = 1; k <= max_doublings; ++k) {
    // W = I + G H in the first block, A and G copied beside it.
    multiply<N, S, false, false, S, S, SW>(G.v, H.v, augmented.v);
    for (int i = 0; i < N; ++i) {
      augmented(i, i) += 1.0;
      std::memcpy(augmented.row(i) + S, A.row(i), sizeof(double) * S);
      std::memcpy(augmented.row(i) + 2 * S, G.row(i), sizeof(double) * S);
    }
    if (!gaussJordan<N, S, SW>(augmented.v)) {
      outcome.finite = false;
      return outcome;
    }
    const double* Y = augmented.v + S;        // W^-1 A
    const double* WinvG = augmented.v + 2 * S;  // W^-1 G (symmetric)

    // H += D with D = A^T (H Y); D is also the change of H for the stopping test.
    multiply<N, S, false, false, S, SW, S>(H.v, Y, Z.v);
    multiply<N, S, true, false, S, S, S>(A.v, Z.v, D.v);
    symmetrize<N, S>(D.v);
    double change_squared = 0.0, norm_squared = 0.0;
    for (int i = 0; i < N * S; ++i) {  // padding columns are zero in both
      H.v[i] += D.v[i];
      change_squared += D.v[i] * D.v[i];
      norm_squared += H.v[i] * H.v[i];
    }

    // G += A (W^-1 G) A^T, formed as A (A (W^-1 G))^T since W^-1 G is symmetric.
    multiply<N, S, false, false, S, SW, S>(A.v, WinvG, T.v);
    for (int i = 0; i < N; ++i) {
      for (int j = 0; j < N; ++j) V(i, j) = T(j, i);
      for (int j = N; j < S; ++j) V(i, j) = 0.0;
    }
    multiply<N, S, false, true, S, S, S>(A.v, V.v, G.v);
    symmetrize<N, S>(G.v);

    // A = A W^-1 A
    multiply<N, S, false, false, S, SW, S>(A.v, Y, T.v);
    A = T;

    const double change = std::sqrt(change_squared / norm_squared);
    if (doublingStops(k, change, tolerance, previous_change, outcome)) return outcome;
  }
  return outcome;
}

// The loop for the x86-64 baseline instruction set (sda_kernel.hpp has the vector versions).
// Only plain double arrays cross these functions, so no Eigen type is compiled with two vector
// settings.
template <int N>
DoublingOutcome doublingLoopBaseline(Block<N, N>& A, Block<N, N>& G, Block<N, N>& H, double tolerance,
                                     int max_doublings) {
  return doublingLoopBody<N>(A, G, H, tolerance, max_doublings);
}

// True when the AVX2 + FMA builds of the kernels may run (kernel_isa.hpp).
inline bool useAvx2Fma() { return activeKernelIsa() != KernelIsa::kBaseline; }

#if defined(SDLQR_SMALL_KERNELS_X86)

// A_k of the doubling falls like rho^(2^k), so the fast modes of a solve underflow into
// subnormal numbers in the late doublings, and x86 cores may take a microcode assist for each
// operation on them. Values below 2^-1022 carry no information for a Riccati solution of order
// 1e-2..1e4, so flush-to-zero / denormals-are-zero are set for the call and then restored.
class FlushSubnormals {
 public:
  FlushSubnormals() : saved_(_mm_getcsr()) { _mm_setcsr(saved_ | 0x8040u); }
  ~FlushSubnormals() { _mm_setcsr(saved_); }
  FlushSubnormals(const FlushSubnormals&) = delete;
  FlushSubnormals& operator=(const FlushSubnormals&) = delete;

 private:
  unsigned saved_;
};
#else
class FlushSubnormals {};
#endif

}  // namespace sdlqr::sda_detail
