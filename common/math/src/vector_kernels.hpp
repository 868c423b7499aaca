#pragma once
// Internal to common/math/src: dense products and helpers for small matrices on L-lane vectors (GCC
// vector extensions): L = 8 is one zmm register (AVX-512), L = 4 one ymm (AVX2). The kernels that
// use them (sda_kernel.hpp, certificate_kernel.hpp) are compiled once per instruction set and
// chosen at run time (kernel_isa.hpp). Matrices are row-major with rows padded to whole vectors;
// all loop bounds are compile-time constants so that the accumulators live in registers.

#include <cmath>
#include <cstring>

#include "small_kernels.hpp"

namespace sdlqr::sda_detail {

// L doubles in one vector: 8 = one zmm register (AVX-512), 4 = one ymm (AVX2), 2 = one xmm.
template <int L>
struct Lanes;
template <>
struct Lanes<8> {
  typedef double Vec __attribute__((vector_size(64)));
  typedef double Unaligned __attribute__((vector_size(64), aligned(8), may_alias));
  typedef long long Mask __attribute__((vector_size(64)));
};
template <>
struct Lanes<4> {
  typedef double Vec __attribute__((vector_size(32)));
  typedef double Unaligned __attribute__((vector_size(32), aligned(8), may_alias));
  typedef long long Mask __attribute__((vector_size(32)));
};
template <>
struct Lanes<2> {
  typedef double Vec __attribute__((vector_size(16)));
  typedef double Unaligned __attribute__((vector_size(16), aligned(8), may_alias));
  typedef long long Mask __attribute__((vector_size(16)));
};

constexpr int roundUp(int n, int multiple) { return (n + multiple - 1) / multiple * multiple; }

// The vector of L doubles at any double-aligned address. Functions here take and return vectors
// by reference only: a vector passed by value would be passed differently by the baseline and
// the AVX-512 compilation (GCC's -Wpsabi).
template <int L>
SDLQR_SDA_INLINE typename Lanes<L>::Unaligned& at(double* p) {
  return *reinterpret_cast<typename Lanes<L>::Unaligned*>(p);
}
template <int L>
SDLQR_SDA_INLINE const typename Lanes<L>::Unaligned& at(const double* p) {
  return *reinterpret_cast<const typename Lanes<L>::Unaligned*>(p);
}

// out(i, v) (+)= sum_{k < K} a(i, k) b(k, v) for ROWS rows from I0 and NV vectors of L lanes;
// a(i, k) is a[i * SA + k], or a[k * SA + i] when kTransposeA. All loops have compile-time bounds
// and are unrolled so that the ROWS * NV accumulators live in registers.
template <int L, int K, int I0, int ROWS, int NV, bool kTransposeA, bool kAccumulate, int SA, int SB, int SO>
SDLQR_SDA_INLINE void productRows(const double* __restrict a, const double* __restrict b, double* __restrict out) {
  using Vec = typename Lanes<L>::Vec;
  Vec accumulator[ROWS][NV];
#pragma GCC unroll 32
  for (int r = 0; r < ROWS; ++r) {
#pragma GCC unroll 8
    for (int v = 0; v < NV; ++v) accumulator[r][v] = kAccumulate ? Vec(at<L>(out + (I0 + r) * SO + L * v)) : Vec{};
  }
#pragma GCC unroll 16
  for (int k = 0; k < K; ++k) {
    Vec b_row[NV];
#pragma GCC unroll 8
    for (int v = 0; v < NV; ++v) b_row[v] = at<L>(b + k * SB + L * v);
#pragma GCC unroll 32
    for (int r = 0; r < ROWS; ++r) {
      const double factor = kTransposeA ? a[k * SA + I0 + r] : a[(I0 + r) * SA + k];
#pragma GCC unroll 8
      for (int v = 0; v < NV; ++v) accumulator[r][v] += factor * b_row[v];
    }
  }
#pragma GCC unroll 32
  for (int r = 0; r < ROWS; ++r) {
#pragma GCC unroll 8
    for (int v = 0; v < NV; ++v) at<L>(out + (I0 + r) * SO + L * v) = accumulator[r][v];
  }
}

// Rows [I0, I1) in blocks of at most kAccumulators / NV rows (the register budget of the ISA).
template <int L, int kAccumulators, int K, int I0, int I1, int NV, bool kTransposeA, bool kAccumulate, int SA,
          int SB, int SO>
SDLQR_SDA_INLINE void product(const double* __restrict a, const double* __restrict b, double* __restrict out) {
  if constexpr (I0 < I1) {
    constexpr int max_rows = kAccumulators / NV > 0 ? kAccumulators / NV : 1;
    constexpr int rows = I1 - I0 < max_rows ? I1 - I0 : max_rows;
    productRows<L, K, I0, rows, NV, kTransposeA, kAccumulate, SA, SB, SO>(a, b, out);
    product<L, kAccumulators, K, I0 + rows, I1, NV, kTransposeA, kAccumulate, SA, SB, SO>(a, b, out);
  }
}

// The lower triangle (and whatever else shares its vectors) of a symmetric N x N product: rows
// [L g, L g + L) need vectors 0..g only.
template <int L, int kAccumulators, int N, int G, bool kTransposeA, int SA, int SB, int SO>
SDLQR_SDA_INLINE void lowerProduct(const double* __restrict a, const double* __restrict b, double* __restrict out) {
  if constexpr (L * G < N) {
    constexpr int end = L * G + L < N ? L * G + L : N;
    product<L, kAccumulators, N, L * G, end, G + 1, kTransposeA, false, SA, SB, SO>(a, b, out);
    lowerProduct<L, kAccumulators, N, G + 1, kTransposeA, SA, SB, SO>(a, b, out);
  }
}

// Completes a symmetric N x N block m (stride S) whose rows were computed by lowerProduct: the
// entries right of a row's last computed vector are copied from their mirror images. The upper
// entries that lowerProduct did compute stay as computed (equal to their mirror images up to
// rounding); the solution is symmetrized once at the end instead of in every doubling.
template <int L, int N, int S>
SDLQR_SDA_INLINE void completeUpper(double* m) {
  for (int i = 0; i < N; ++i) {
    for (int j = (i / L + 1) * L; j < N; ++j) m[i * S + j] = m[j * S + i];
  }
}

// out = a^T for an N x N block a (stride SA) into out (stride SO): whole L x L blocks by vector
// shuffles (at each level h, the lanes with bit h set in row r swap with the lanes with bit h
// clear in row r + h), the remaining edge entries one by one.
template <int L, int N, int SA, int SO>
SDLQR_SDA_INLINE void transpose(const double* __restrict a, double* __restrict out) {
#if defined(__clang__)
  constexpr int B = 0;  // __builtin_shuffle is GCC's: element by element
#else
  using Vec = typename Lanes<L>::Vec;
  using Mask = typename Lanes<L>::Mask;
  constexpr int B = N / L * L;  // rows and columns covered by whole blocks
  for (int i0 = 0; i0 < B; i0 += L) {
    for (int j0 = 0; j0 < B; j0 += L) {
      Vec rows[L];
#pragma GCC unroll 8
      for (int r = 0; r < L; ++r) rows[r] = at<L>(a + (i0 + r) * SA + j0);
#pragma GCC unroll 4
      for (int h = 1; h < L; h *= 2) {
        Mask low = {}, high = {};
        for (int j = 0; j < L; ++j) {
          low[j] = (j & h) ? L + j - h : j;     // row r keeps its lanes without bit h
          high[j] = (j & h) ? L + j : j + h;  // row r + h keeps its lanes with bit h
        }
#pragma GCC unroll 8
        for (int r = 0; r < L; ++r) {
          if (r & h) continue;
          const Vec upper = rows[r], lower = rows[r + h];
          rows[r] = __builtin_shuffle(upper, lower, low);
          rows[r + h] = __builtin_shuffle(upper, lower, high);
        }
      }
#pragma GCC unroll 8
      for (int r = 0; r < L; ++r) at<L>(out + (j0 + r) * SO + i0) = rows[r];
    }
  }
#endif
  for (int i = 0; i < N; ++i) {
    for (int j = i < B ? B : 0; j < N; ++j) out[j * SO + i] = a[i * SA + j];
  }
}

// One pivot step P of an in-place Gauss-Jordan elimination with partial pivoting of [W | rhs]
// (N rows, stride SW, a multiple of L; W in columns 0..N-1), then the steps after it: afterwards
// the columns right of W hold W^-1 rhs. False when a pivot is zero or non-finite. Every step is
// its own instantiation, so all loop bounds are constants and the rows are updated without
// branches; the pivot row is exchanged unconditionally (with itself when no exchange is due).
template <int L, int N, int SW, int P>
SDLQR_SDA_INLINE bool gaussJordanFrom(double* m) {
  if constexpr (P == N) {
    return true;
  } else {
    using Vec = typename Lanes<L>::Vec;
    constexpr int NV = SW / L;
    constexpr int first = P / L;  // vectors left of it hold finished unit columns only
    // Partial pivoting: the first row from P with the largest |m(i, P)|. The compare-and-branch
    // search is deliberate: its branches are well predicted in the repetitive doubling, and a
    // predicted pivot lets the division start before the search has finished (a branch-free
    // tournament measured 15 % slower in the whole loop).
    int pivot_row = P;
    double pivot_value = m[P * SW + P];
    double pivot_abs = std::fabs(pivot_value);
#pragma GCC unroll 16
    for (int i = P + 1; i < N; ++i) {
      const double candidate = m[i * SW + P];
      const bool larger = std::fabs(candidate) > pivot_abs;
      pivot_abs = larger ? std::fabs(candidate) : pivot_abs;
      pivot_value = larger ? candidate : pivot_value;
      pivot_row = larger ? i : pivot_row;
    }
    if (!(pivot_abs > 0.0) || !std::isfinite(pivot_abs)) return false;
    double* __restrict pivot = m + P * SW;
    double* other = m + pivot_row * SW;
    const double inverse = 1.0 / pivot_value;
    Vec scaled[NV] = {};
#pragma GCC unroll 16
    for (int v = first; v < NV; ++v) {
      const Vec old_row = at<L>(pivot + L * v);
      scaled[v] = inverse * at<L>(other + L * v);
      at<L>(other + L * v) = old_row;
    }
#pragma GCC unroll 16
    for (int v = first; v < NV; ++v) at<L>(pivot + L * v) = scaled[v];
#pragma GCC unroll 16
    for (int i = 0; i < N; ++i) {
      if (i == P) continue;
      double* __restrict target = m + i * SW;
      const double factor = target[P];
#pragma GCC unroll 16
      for (int v = first; v < NV; ++v) at<L>(target + L * v) -= factor * scaled[v];
    }
    return gaussJordanFrom<L, N, SW, P + 1>(m);
  }
}

}  // namespace sdlqr::sda_detail
