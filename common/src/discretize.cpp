#include "sdlqr/common/discretize.hpp"

#include <cmath>
#include <limits>

#include <Eigen/LU>

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

template <int NX, int NU>
DiscreteSystem<NX, NU> discretizeZoh(const Eigen::Matrix<double, NX, NX>& A, const Eigen::Matrix<double, NX, NU>& B,
                                     double dt) {
  SquareMatrix<NX + NU> augmented = SquareMatrix<NX + NU>::Zero();
  augmented.template topLeftCorner<NX, NX>() = A * dt;
  augmented.template topRightCorner<NX, NU>() = B * dt;
  const SquareMatrix<NX + NU> exponential = expm<NX + NU>(augmented);
  DiscreteSystem<NX, NU> discrete;
  discrete.A = exponential.template topLeftCorner<NX, NX>();
  discrete.B = exponential.template topRightCorner<NX, NU>();
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

}  // namespace sdlqr
