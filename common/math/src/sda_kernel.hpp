#pragma once
// Internal to common/math/src (riccati.cpp): the structure-preserving doubling loop on L-lane vectors
// (GCC vector extensions): L = 8, one zmm register, with AVX-512; L = 4, one ymm, with AVX2. The
// same source is compiled once per instruction set and chosen at run time (kernel_isa.hpp); the
// x86-64 baseline keeps the loop of small_kernels.hpp. Every row is a whole number of vectors.
// Per doubling (see riccati.hpp):
//
//   [W | A | G] with W = I + G H, the three N-column blocks packed side by side (27 of 32 columns
//   for N = 9, four zmm vectors a row) -> one Gauss-Jordan elimination -> [I | Y | S_G],
//   Y = W^-1 A, S_G = W^-1 G (symmetric);
//   D_H = A^T (H Y)              H <- H + D_H, D_H also the change for the stopping test;
//   [A' | T] = A [Y | S_G]       one product for both (their columns are adjacent);
//   D_G = T A^T = A S_G A^T      G <- G + D_G.
//
// D_H and D_G are symmetric: only the vectors that hold their lower triangle are computed and the
// missing upper entries are copied from it; the returned H is symmetrized. The last doubling stops
// after the H update: A' and G' are not needed once the stopping test passes.
//
// Padding columns: H, G and D keep zero padding (updates are masked to the real lanes); the
// other blocks may hold finite "don't care" values there, which never reach a real entry because
// a product reads only the real columns of its left operand.

#include <cmath>
#include <cstring>

#include "small_kernels.hpp"
#include "vector_kernels.hpp"

namespace sdlqr::sda_detail {

// The doubling state in its padded layouts (rows a whole number of L-lane vectors). A lives
// inside a [x | A | T]-shaped block (stride SW) because the product that forms A' also forms T;
// two such blocks alternate.
template <int N, int L>
struct DoublingWorkspace {
  static constexpr int S = roundUp(N, L);       // stride of the N x N blocks
  static constexpr int SW = roundUp(3 * N, L);  // stride of [W | A | G]
  alignas(64) double gj[N * SW + L];            // + L: an unaligned read of Y may run past the last row
  alignas(64) double a_blocks[2][N * SW];
  alignas(64) double G[N * S];
  alignas(64) double H[N * S];
  alignas(64) double At[N * S];
  alignas(64) double Z[N * S];
  alignas(64) double D[N * S];
};

// The SDA loop (riccati.hpp) on dense row-major N x N inputs A, G, H (stride N); H is
// overwritten with the solution estimate. L: lanes of the target's vector register;
// kAccumulators: how many such vectors one product block may keep as accumulators.
template <int N, int L, int kAccumulators>
SDLQR_SDA_INLINE DoublingOutcome doublingLoopVectorBody(const double* A_in, const double* G_in, double* H_inout,
                                                   double tolerance, int max_doublings) {
  using Workspace = DoublingWorkspace<N, L>;
  constexpr int S = Workspace::S;
  constexpr int SW = Workspace::SW;
  using Vec = typename Lanes<L>::Vec;
  using Mask = typename Lanes<L>::Mask;
  constexpr int NS = S / L;          // vectors per N x N row
  constexpr int c0 = N / L * L;      // first vector boundary at or left of Y
  constexpr int NR = (SW - c0) / L;  // vectors from c0 to the end of a [W | A | G] row
  Workspace w;
  std::memset(&w, 0, sizeof w);
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      w.a_blocks[0][i * SW + N + j] = A_in[i * N + j];
      w.G[i * S + j] = G_in[i * N + j];
      w.H[i * S + j] = H_inout[i * N + j];
    }
  }
  double* A_block = w.a_blocks[0];
  double* A_next = w.a_blocks[1];

  Mask lane_index = {};  // a lane of vector v is real when L v + index < N
  for (int j = 0; j < L; ++j) lane_index[j] = j;

  DoublingOutcome outcome;
  double previous_change = HUGE_VAL;
  for (int k = 1; k <= max_doublings; ++k) {
    const double* A = A_block + N;  // A(i, j) = A[i * SW + j]
    // W = I + G H, then A and G beside it (the product's padding columns are overwritten).
    product<L, kAccumulators, N, 0, N, NS, false, false, S, S, SW>(w.G, w.H, w.gj);
    for (int i = 0; i < N; ++i) {
      w.gj[i * SW + i] += 1.0;
      std::memcpy(w.gj + i * SW + N, A + i * SW, sizeof(double) * N);
      std::memcpy(w.gj + i * SW + 2 * N, w.G + i * S, sizeof(double) * N);
    }
    // A^T for the G update; independent of the elimination, so it fills the elimination's stalls.
    transpose<L, N, SW, S>(A, w.At);
    if (!gaussJordanFrom<L, N, SW, 0>(w.gj)) {
      outcome.finite = false;
      return outcome;
    }
    const double* Y = w.gj + N;  // W^-1 A, stride SW

    // H += D_H, D_H = A^T (H Y).
    product<L, kAccumulators, N, 0, N, NS, false, false, S, SW, S>(w.H, Y, w.Z);
    lowerProduct<L, kAccumulators, N, 0, true, SW, S, S>(A, w.Z, w.D);
    completeUpper<L, N, S>(w.D);
    Vec change_squared{}, norm_squared{};
    for (int i = 0; i < N; ++i) {
#pragma GCC unroll 16
      for (int v = 0; v < NS; ++v) {
        const Vec d = lane_index + L * v < N ? Vec(at<L>(w.D + i * S + L * v)) : Vec{};
        const Vec h = at<L>(w.H + i * S + L * v) + d;
        at<L>(w.H + i * S + L * v) = h;
        change_squared += d * d;
        norm_squared += h * h;
      }
    }
    double change_sum = 0.0, norm_sum = 0.0;
    for (int j = 0; j < L; ++j) {
      change_sum += change_squared[j];
      norm_sum += norm_squared[j];
    }
    const double change = std::sqrt(change_sum / norm_sum);
    if (doublingStops(k, change, tolerance, previous_change, outcome)) {
      if (!outcome.finite) return outcome;
      break;  // converged: H is symmetrized below
    }
    if (k == max_doublings) break;

    // [A' | T] = A [Y | S_G] in one product over the vectors from c0 on.
    product<L, kAccumulators, N, 0, N, NR, false, false, SW, SW, SW>(A, w.gj + c0, A_next + c0);
    // G += D_G, D_G = T A^T.
    lowerProduct<L, kAccumulators, N, 0, false, SW, S, S>(A_next + 2 * N, w.At, w.D);
    completeUpper<L, N, S>(w.D);
    for (int i = 0; i < N; ++i) {
#pragma GCC unroll 16
      for (int v = 0; v < NS; ++v) {
        const Vec d = lane_index + L * v < N ? Vec(at<L>(w.D + i * S + L * v)) : Vec{};
        at<L>(w.G + i * S + L * v) += d;
      }
    }
    double* const swap = A_block;
    A_block = A_next;
    A_next = swap;
  }
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) H_inout[i * N + j] = 0.5 * (w.H[i * S + j] + w.H[j * S + i]);
  }
  return outcome;
}

// The vector loop compiled per instruction set (measured on the 9-state problems, Zen 5, us per
// loop: AVX-512 3.8, AVX2 5.3; the previous 4-wide loop 7.3). Accumulator budgets: 24 of the
// 32 zmm registers; 9 of the 16 ymm (the rest hold the right-hand rows and the broadcast).
template <int N>
SDLQR_AVX512_TARGET DoublingOutcome doublingLoopAvx512(const double* A, const double* G, double* H, double tolerance,
                                                       int max_doublings) {
  return doublingLoopVectorBody<N, 8, 24>(A, G, H, tolerance, max_doublings);
}

template <int N>
SDLQR_AVX2_TARGET DoublingOutcome doublingLoopAvx2(const double* A, const double* G, double* H, double tolerance,
                                                   int max_doublings) {
  return doublingLoopVectorBody<N, 4, 9>(A, G, H, tolerance, max_doublings);
}

// The SDA loop on dense row-major N x N arrays (H in: Q, out: the solution estimate), on the
// instruction set of activeKernelIsa(). The baseline build keeps the loop of small_kernels.hpp:
// fully unrolled 2-lane code is several times larger than the instruction cache and slower.
template <int N>
DoublingOutcome doublingLoop(const double* A, const double* G, double* H, double tolerance, int max_doublings) {
  const FlushSubnormals flush;
  switch (activeKernelIsa()) {
    case KernelIsa::kAvx512: return doublingLoopAvx512<N>(A, G, H, tolerance, max_doublings);
    case KernelIsa::kAvx2Fma: return doublingLoopAvx2<N>(A, G, H, tolerance, max_doublings);
    default: break;
  }
  Block<N, N> a{}, g{}, h{};
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) {
      a(i, j) = A[i * N + j];
      g(i, j) = G[i * N + j];
      h(i, j) = H[i * N + j];
    }
  }
  const DoublingOutcome outcome = doublingLoopBaseline<N>(a, g, h, tolerance, max_doublings);
  for (int i = 0; i < N; ++i) {
    for (int j = 0; j < N; ++j) H[i * N + j] = h(i, j);
  }
  return outcome;
}

}  // namespace sdlqr::sda_detail
