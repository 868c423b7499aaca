#include "sdlqr/math/discretize.hpp"

#include <cmath>
#include <limits>

#include <Eigen/LU>

#include "small_kernels.hpp"
#include "vector_kernels.hpp"

namespace sdlqr {

namespace {

// Backward-error bounds theta_m of the [m/m] Padé approximant in double precision (Higham 2005, Table 2.3).
constexpr double kTheta3 = 1.495585217958292e-2;
constexpr double kTheta5 = 2.539398330063230e-1;
constexpr double kTheta7 = 9.504178996162932e-1;
constexpr double kTheta9 = 2.097847961257068e0;
constexpr double kTheta13 = 5.371920351148152e0;

template <int N>
double oneNorm(const SquareMatrix<N>& M) {
  return M.cwiseAbs().colwise().sum().maxCoeff();
}

// r_m(M) = (V - U)^-1 (V + U), U odd and V even part of the Padé numerator.
template <int N>
SquareMatrix<N> padeQuotient(const SquareMatrix<N>& U, const SquareMatrix<N>& V) {
  const SquareMatrix<N> numerator = V + U;
  const SquareMatrix<N> denominator = V - U;
  return Eigen::PartialPivLU<SquareMatrix<N>>(denominator).solve(numerator);
}

// Degrees 3..9: U = M sum b_odd M^(j-1), V = sum b_even M^j, with the even powers computed once.
template <int N, int Degree>
SquareMatrix<N> padeLowDegree(const SquareMatrix<N>& M) {
  static_assert(Degree == 3 || Degree == 5 || Degree == 7 || Degree == 9, "low degrees only");
  constexpr double b3[] = {120.0, 60.0, 12.0, 1.0};
  constexpr double b5[] = {30240.0, 15120.0, 3360.0, 420.0, 30.0, 1.0};
  constexpr double b7[] = {17297280.0, 8648640.0, 1995840.0, 277200.0, 25200.0, 1512.0, 56.0, 1.0};
  constexpr double b9[] = {17643225600.0, 8821612800.0, 2075673600.0, 302702400.0, 30270240.0,
                           2162160.0,     110880.0,     3960.0,       90.0,        1.0};
  const double* b = Degree == 3 ? b3 : Degree == 5 ? b5 : Degree == 7 ? b7 : b9;

  const SquareMatrix<N> identity = SquareMatrix<N>::Identity();
  const SquareMatrix<N> M2 = M * M;
  SquareMatrix<N> power = M2;  // M^2, then M^4, ...
  SquareMatrix<N> odd = b[1] * identity + b[3] * power;
  SquareMatrix<N> even = b[0] * identity + b[2] * power;
  for (int j = 4; j < Degree; j += 2) {
    const SquareMatrix<N> next = power * M2;
    power = next;
    odd += b[j + 1] * power;
    even += b[j] * power;
  }
  const SquareMatrix<N> U = M * odd;
  return padeQuotient<N>(U, even);
}

template <int N>
SquareMatrix<N> pade13(const SquareMatrix<N>& M) {
  constexpr double b[] = {64764752532480000.0, 32382376266240000.0, 7771770303897600.0, 1187353796428800.0,
                          129060195264000.0,   10559470521600.0,    670442572800.0,     33522128640.0,
                          1323241920.0,        40840800.0,          960960.0,           16380.0,
                          182.0,               1.0};
  const SquareMatrix<N> identity = SquareMatrix<N>::Identity();
  const SquareMatrix<N> M2 = M * M;
  const SquareMatrix<N> M4 = M2 * M2;
  const SquareMatrix<N> M6 = M4 * M2;
  const SquareMatrix<N> odd_high = b[13] * M6 + b[11] * M4 + b[9] * M2;
  const SquareMatrix<N> odd = M6 * odd_high + b[7] * M6 + b[5] * M4 + b[3] * M2 + b[1] * identity;
  const SquareMatrix<N> U = M * odd;
  const SquareMatrix<N> even_high = b[12] * M6 + b[10] * M4 + b[8] * M2;
  const SquareMatrix<N> V = M6 * even_high + b[6] * M6 + b[4] * M4 + b[2] * M2 + b[0] * identity;
  return padeQuotient<N>(U, V);
}

}  // namespace

template <int N>
SquareMatrix<N> expm(const SquareMatrix<N>& M) {
  const double norm = oneNorm<N>(M);
  if (!std::isfinite(norm)) return SquareMatrix<N>::Constant(std::numeric_limits<double>::quiet_NaN());
  if (norm <= kTheta3) return padeLowDegree<N, 3>(M);
  if (norm <= kTheta5) return padeLowDegree<N, 5>(M);
  if (norm <= kTheta7) return padeLowDegree<N, 7>(M);
  if (norm <= kTheta9) return padeLowDegree<N, 9>(M);
  const int squarings = norm <= kTheta13 ? 0 : static_cast<int>(std::ceil(std::log2(norm / kTheta13)));
  SquareMatrix<N> result = pade13<N>(M * std::ldexp(1.0, -squarings));
  for (int i = 0; i < squarings; ++i) {
    const SquareMatrix<N> squared = result * result;
    result = squared;
  }
  return result;
}

namespace {

using namespace sda_detail;

// The ZOH exponential exploits the shape of M = [[F, Gamma], [0, 0]] (F = A dt, Gamma = B dt):
// every power is [[F^j, F^(j-1) Gamma], [0, 0]], so only the NX top rows are stored (T(M^j) below)
// and T(M^(a+b)) = F^a T(M^b) is an NX x NX by NX x (NX+NU) product. The Padé quotient is block
// triangular with [[D, -U_Gamma], [0, b0 I]] as denominator (D = V_F - U_F): its top rows are
// D^-1 [V_F + U_F | 2 U_Gamma] and its bottom rows [0 | I]. Squaring keeps the form:
// [E | Phi] -> E [E | Phi] + [0 | Phi].
//
// kVector: the products and the elimination of vector_kernels.hpp on L-lane vectors, the
// elimination on [D | rhs] packed into whole vectors; else the auto-vectorized loops of
// small_kernels.hpp (baseline build, L = 4 layout).

// The vector product of two top-row blocks, one out-of-line copy per instruction set: inlined at
// each of its call sites (one per Padé degree) it made the exponential 55 KB of code, most of it
// cold, which costs instruction-cache misses in every solve.
template <int NX, int SP>
SDLQR_AVX512_TARGET __attribute__((noinline)) void zohProductAvx512(const double* a, const double* b, double* out) {
  product<8, 24, NX, 0, NX, SP / 8, false, false, SP, SP, SP>(a, b, out);
}

template <int NX, int SP>
SDLQR_AVX2_TARGET __attribute__((noinline)) void zohProductAvx2(const double* a, const double* b, double* out) {
  product<4, 9, NX, 0, NX, SP / 4, false, false, SP, SP, SP>(a, b, out);
}

template <int NX, int NU, int L, bool kVector>
struct ZohKernel {
  static constexpr int NP = NX + NU;
  static constexpr int SP = roundUp(NP, L);
  // [D | rhs] for the Gauss-Jordan solve: packed (rhs from column NX) or each block padded.
  static constexpr int RHS = kVector ? NX : padded(NX);
  static constexpr int SG = kVector ? roundUp(NX + NP, L) : padded(NX) + SP;
  using Top = Block<NX, NP, SP>;

  // out = first NX columns of `left` (an F power) times `right`.
  static SDLQR_SDA_INLINE void product(const Top& left, const Top& right, Top& out) {
    if constexpr (kVector && L == 8) {
      zohProductAvx512<NX, SP>(left.v, right.v, out.v);
    } else if constexpr (kVector) {
      zohProductAvx2<NX, SP>(left.v, right.v, out.v);
    } else {
      multiply<NX, SP, false, false, SP, SP, SP>(left.v, right.v, out.v);
    }
  }
  static SDLQR_SDA_INLINE void axpy(double a, const Top& x, Top& y) {
    for (int i = 0; i < NX * SP; ++i) y.v[i] += a * x.v[i];
  }
  static SDLQR_SDA_INLINE void scaled(double a, const Top& x, Top& y) {
    for (int i = 0; i < NX * SP; ++i) y.v[i] = a * x.v[i];
  }
  // The degree-13 Pade sums (Higham 2005) from the powers M2, M4, M6 and the coefficients b:
  // out = M6 (b[12+k] M6 + b[10+k] M4 + b[8+k] M2) + b[6+k] M6 + b[4+k] M4 + b[2+k] M2, the odd
  // sum without M1 (k = 1) or the even sum without b[0] (k = 0). One order of operations for both.
  static SDLQR_SDA_INLINE void pade13Sum(const double* b, int k, const Top& M2, const Top& M4, const Top& M6,
                                         Top& out) {
    Top inner;
    scaled(b[12 + k], M6, inner);
    axpy(b[10 + k], M4, inner);
    axpy(b[8 + k], M2, inner);
    product(M6, inner, out);
    axpy(b[6 + k], M6, out);
    axpy(b[4 + k], M4, out);
    axpy(b[2 + k], M2, out);
  }

  // Fills `result` with the top rows of exp(M), M given by its top rows; false on a singular D.
  static SDLQR_SDA_INLINE bool run(const Top& m_top, double norm, Top& result) {
    int degree = 13, squarings = 0;
    if (norm <= kTheta3) degree = 3;
    else if (norm <= kTheta5) degree = 5;
    else if (norm <= kTheta7) degree = 7;
    else if (norm <= kTheta9) degree = 9;
    else if (norm > kTheta13) squarings = static_cast<int>(std::ceil(std::log2(norm / kTheta13)));

    Top M1;
    scaled(std::ldexp(1.0, -squarings), m_top, M1);
    Top M2, M4, M6, M8, odd_rest, U, V;
    product(M1, M1, M2);
    for (int i = 0; i < NX * SP; ++i) odd_rest.v[i] = V.v[i] = 0.0;
    if (degree < 13) {
      static constexpr double b3[] = {120.0, 60.0, 12.0, 1.0};
      static constexpr double b5[] = {30240.0, 15120.0, 3360.0, 420.0, 30.0, 1.0};
      static constexpr double b7[] = {17297280.0, 8648640.0, 1995840.0, 277200.0, 25200.0, 1512.0, 56.0, 1.0};
      static constexpr double b9[] = {17643225600.0, 8821612800.0, 2075673600.0, 302702400.0, 30270240.0,
                                      2162160.0,     110880.0,     3960.0,       90.0,        1.0};
      const double* b = degree == 3 ? b3 : degree == 5 ? b5 : degree == 7 ? b7 : b9;
      axpy(b[3], M2, odd_rest);
      axpy(b[2], M2, V);
      // Each further degree: the next even power, M2 times the last, into both sums.
      Top* const powers[] = {&M2, &M4, &M6, &M8};
      for (int k = 1; 2 * k + 3 <= degree; ++k) {
        product(*powers[k - 1], M2, *powers[k]);
        axpy(b[2 * k + 3], *powers[k], odd_rest);
        axpy(b[2 * k + 2], *powers[k], V);
      }
      finish(M1, odd_rest, b[1], b[0], V, U);
    } else {
      static constexpr double b[] = {64764752532480000.0, 32382376266240000.0, 7771770303897600.0,
                                     1187353796428800.0,  129060195264000.0,   10559470521600.0,
                                     670442572800.0,      33522128640.0,       1323241920.0,
                                     40840800.0,          960960.0,            16380.0,
                                     182.0,               1.0};
      product(M2, M2, M4);
      product(M4, M2, M6);
      pade13Sum(b, 1, M2, M4, M6, odd_rest);
      pade13Sum(b, 0, M2, M4, M6, V);
      finish(M1, odd_rest, b[1], b[0], V, U);
    }

    // [D | V_F + U_F | 2 U_Gamma] with D = V_F - U_F, then Gauss-Jordan.
    Block<NX, SG, SG> system;
    for (int i = 0; i < NX; ++i) {
      for (int j = 0; j < RHS; ++j) system(i, j) = j < NX ? V(i, j) - U(i, j) : 0.0;
      for (int j = 0; j < SG - RHS; ++j) {
        system(i, RHS + j) = j < NX ? V(i, j) + U(i, j) : j < NP ? 2.0 * U(i, j) : 0.0;
      }
    }
    bool solved;
    if constexpr (kVector) {
      solved = gaussJordanFrom<L, NX, SG, 0>(system.v);
    } else {
      solved = gaussJordan<NX, RHS, SG>(system.v);
    }
    if (!solved) return false;
    for (int i = 0; i < NX; ++i) {
      for (int j = 0; j < SP; ++j) result(i, j) = j < NP ? system(i, RHS + j) : 0.0;
    }
    for (int k = 0; k < squarings; ++k) {
      Top squared;
      product(result, result, squared);
      for (int i = 0; i < NX; ++i) {
        for (int j = NX; j < NP; ++j) squared(i, j) += result(i, j);
      }
      result = squared;
    }
    return true;
  }

  // U = b1 T(M) + F odd_rest; V gets b0 [I | 0] added.
  static SDLQR_SDA_INLINE void finish(const Top& M1, const Top& odd_rest, double b1, double b0, Top& V, Top& U) {
    product(M1, odd_rest, U);
    axpy(b1, M1, U);
    for (int i = 0; i < NX; ++i) V(i, i) += b0;
  }
};

// One build per instruction set (kernel_isa.hpp); all take and give the top rows in the L = 8
// layout (a multiple of the L = 4 one), so the kernels of other widths copy in and out.
template <int NX, int NU>
using ZohTop = Block<NX, NX + NU, roundUp(NX + NU, 8)>;

template <int NX, int NU, int L, bool kVector>
SDLQR_SDA_INLINE bool zohExponentialIn(const ZohTop<NX, NU>& m_top, double norm, ZohTop<NX, NU>& out) {
  using Kernel = ZohKernel<NX, NU, L, kVector>;
  if constexpr (Kernel::SP == roundUp(NX + NU, 8)) {
    return Kernel::run(m_top, norm, out);
  } else {
    typename Kernel::Top in, result;
    for (int i = 0; i < NX; ++i) {
      for (int j = 0; j < Kernel::SP; ++j) in(i, j) = m_top(i, j);
    }
    if (!Kernel::run(in, norm, result)) return false;
    for (int i = 0; i < NX; ++i) {
      for (int j = 0; j < roundUp(NX + NU, 8); ++j) out(i, j) = j < Kernel::SP ? result(i, j) : 0.0;
    }
    return true;
  }
}

template <int NX, int NU>
SDLQR_AVX512_TARGET bool zohExponentialAvx512(const ZohTop<NX, NU>& m_top, double norm, ZohTop<NX, NU>& out) {
  return zohExponentialIn<NX, NU, 8, true>(m_top, norm, out);
}

template <int NX, int NU>
SDLQR_AVX2_TARGET bool zohExponentialAvx2(const ZohTop<NX, NU>& m_top, double norm, ZohTop<NX, NU>& out) {
  return zohExponentialIn<NX, NU, 4, true>(m_top, norm, out);
}

template <int NX, int NU>
bool zohExponentialBaseline(const ZohTop<NX, NU>& m_top, double norm, ZohTop<NX, NU>& out) {
  return zohExponentialIn<NX, NU, 4, false>(m_top, norm, out);
}

template <int NX, int NU>
bool zohExponential(const ZohTop<NX, NU>& m_top, double norm, ZohTop<NX, NU>& out) {
  switch (activeKernelIsa()) {
    case KernelIsa::kAvx512: return zohExponentialAvx512<NX, NU>(m_top, norm, out);
    case KernelIsa::kAvx2Fma: return zohExponentialAvx2<NX, NU>(m_top, norm, out);
    default: return zohExponentialBaseline<NX, NU>(m_top, norm, out);
  }
}

}  // namespace

template <int NX, int NU>
DiscreteSystem<NX, NU> discretizeZoh(const Eigen::Matrix<double, NX, NX>& A, const Eigen::Matrix<double, NX, NU>& B,
                                     double dt) {
  using Top = ZohTop<NX, NU>;
  constexpr int NP = NX + NU;
  Top m_top, result;
  double column_sums[NP] = {};
  for (int i = 0; i < NX; ++i) {
    for (int j = 0; j < sda_detail::roundUp(NP, 8); ++j) {
      const double value = j < NX ? A(i, j) * dt : j < NP ? B(i, j - NX) * dt : 0.0;
      m_top(i, j) = value;
      if (j < NP) column_sums[j] += std::fabs(value);
    }
  }
  double norm = 0.0;
  for (int j = 0; j < NP; ++j) norm = std::fmax(norm, column_sums[j]);
  if (!std::isfinite(norm) || !std::isfinite(dt)) norm = std::numeric_limits<double>::quiet_NaN();

  DiscreteSystem<NX, NU> discrete;
  const FlushSubnormals flush;
  const bool ok = std::isfinite(norm) && zohExponential<NX, NU>(m_top, norm, result);
  if (!ok) {
    discrete.A.setConstant(std::numeric_limits<double>::quiet_NaN());
    discrete.B.setConstant(std::numeric_limits<double>::quiet_NaN());
    return discrete;
  }
  for (int i = 0; i < NX; ++i) {
    for (int j = 0; j < NX; ++j) discrete.A(i, j) = result(i, j);
    for (int j = 0; j < NU; ++j) discrete.B(i, j) = result(i, NX + j);
  }
  return discrete;
}

template SquareMatrix<2> expm<2>(const SquareMatrix<2>&);
template SquareMatrix<3> expm<3>(const SquareMatrix<3>&);
template SquareMatrix<13> expm<13>(const SquareMatrix<13>&);
template SquareMatrix<14> expm<14>(const SquareMatrix<14>&);
template DiscreteSystem<2, 1> discretizeZoh<2, 1>(const Eigen::Matrix<double, 2, 2>&, const Eigen::Matrix<double, 2, 1>&,
                                                  double);
template DiscreteSystem<9, 4> discretizeZoh<9, 4>(const Eigen::Matrix<double, 9, 9>&, const Eigen::Matrix<double, 9, 4>&,
                                                  double);
template DiscreteSystem<10, 4> discretizeZoh<10, 4>(const Eigen::Matrix<double, 10, 10>&,
                                                    const Eigen::Matrix<double, 10, 4>&, double);
template DiscreteSystem<12, 4> discretizeZoh<12, 4>(const Eigen::Matrix<double, 12, 12>&,
                                                    const Eigen::Matrix<double, 12, 4>&, double);

}  // namespace sdlqr
