// Zero-order-hold discretization and the fixed-size matrix exponential, against closed forms and
// an independent Taylor series evaluated in long double.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "sdlqr/math/discretize.hpp"
#include "sdlqr/math/kernel_isa.hpp"
#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/quaternion.hpp"

namespace sdlqr {
namespace {

template <int N>
using LongMatrix = Eigen::Matrix<long double, N, N>;

// exp(M) by scaling by 2^-s (||M|| 2^-s <= 1/8), a 30-term Taylor series and s squarings, in
// long double: slow but simple and unrelated to the Padé code under test.
template <int N>
SquareMatrix<N> taylorExp(const SquareMatrix<N>& M) {
  const long double norm = M.template cast<long double>().cwiseAbs().colwise().sum().maxCoeff();
  int squarings = 0;
  while (std::ldexp(norm, -squarings) > 0.125L) ++squarings;
  const LongMatrix<N> scaled = M.template cast<long double>() * std::ldexp(1.0L, -squarings);
  LongMatrix<N> term = LongMatrix<N>::Identity();
  LongMatrix<N> sum = LongMatrix<N>::Identity();
  for (int k = 1; k <= 30; ++k) {
    term = (term * scaled / static_cast<long double>(k)).eval();
    sum += term;
  }
  for (int i = 0; i < squarings; ++i) sum = (sum * sum).eval();
  return sum.template cast<double>();
}

// Every instruction set of the kernels that this CPU supports (kernel_isa.hpp); the best one is
// restored when the test ends.
struct EachKernelIsa {
  std::vector<KernelIsa> isas;
  EachKernelIsa() {
    for (const KernelIsa isa : {KernelIsa::kBaseline, KernelIsa::kAvx2Fma, KernelIsa::kAvx512}) {
      if (static_cast<int>(isa) <= static_cast<int>(bestKernelIsa())) isas.push_back(isa);
    }
  }
  ~EachKernelIsa() { setKernelIsa(bestKernelIsa()); }
};

template <int N>
double relativeError(const SquareMatrix<N>& actual, const SquareMatrix<N>& expected) {
  return (actual - expected).cwiseAbs().maxCoeff() / expected.cwiseAbs().maxCoeff();
}

// The worst error of discretizeZoh's Ad and Bd against the Taylor series of exp([A B; 0 0] dt),
// relative to that exponential's largest entry.
template <int NX, int NU>
double zohErrorAgainstTaylor(const Eigen::Matrix<double, NX, NX>& A, const Eigen::Matrix<double, NX, NU>& B,
                             double dt) {
  const DiscreteSystem<NX, NU> zoh = discretizeZoh<NX, NU>(A, B, dt);
  SquareMatrix<NX + NU> augmented = SquareMatrix<NX + NU>::Zero();
  augmented.template topLeftCorner<NX, NX>() = A * dt;
  augmented.template topRightCorner<NX, NU>() = B * dt;
  const SquareMatrix<NX + NU> reference = taylorExp<NX + NU>(augmented);
  return std::max((zoh.A - reference.template topLeftCorner<NX, NX>()).cwiseAbs().maxCoeff(),
                  (zoh.B - reference.template topRightCorner<NX, NU>()).cwiseAbs().maxCoeff()) /
         reference.cwiseAbs().maxCoeff();
}

TEST(Expm, RotationGeneratorGivesRotationMatrixAtEveryPadeDegreeAndWithSquaring) {
  // ||M||_1 = angle: 0.01 (degree 3), 0.2 (5), 0.9 (7), 2 (9), 5 (13), 40 (13 with 3 squarings).
  for (const double angle : {0.01, 0.2, 0.9, 2.0, 5.0, 40.0}) {
    SquareMatrix<2> M;
    M << 0.0, angle, -angle, 0.0;
    SquareMatrix<2> expected;
    expected << std::cos(angle), std::sin(angle), -std::sin(angle), std::cos(angle);
    const double error = (expm<2>(M) - expected).cwiseAbs().maxCoeff();
    std::cout << "angle " << angle << ": error " << error << "\n";
    EXPECT_LT(error, 1e-14 * std::max(1.0, angle)) << "angle " << angle;
  }
}

TEST(Expm, NilpotentJordanBlockIsExact) {
  SquareMatrix<3> M;
  M << 0, 1, 0, 0, 0, 1, 0, 0, 0;
  M *= 3.0;  // exp = I + M + M^2/2
  SquareMatrix<3> expected;
  expected << 1, 3, 4.5, 0, 1, 3, 0, 0, 1;
  EXPECT_LT((expm<3>(M) - expected).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Expm, NonFiniteInputGivesNonFiniteOutputWithoutCrashing) {
  SquareMatrix<13> M = SquareMatrix<13>::Zero();
  M(2, 5) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(expm<13>(M).allFinite());
}

TEST(Zoh, DoubleIntegratorMatchesClosedFormForSeveralSteps) {
  Eigen::Matrix2d A;
  A << 0, 1, 0, 0;
  const Eigen::Vector2d B(0, 1);
  const EachKernelIsa each;
  for (const KernelIsa isa : each.isas) {
  SCOPED_TRACE(toString(isa));
  setKernelIsa(isa);
  for (const double dt : {1e-4, 0.002, 0.01, 0.1, 1.0, 7.5}) {
    const DiscreteSystem<2, 1> d = discretizeZoh<2, 1>(A, B, dt);
    Eigen::Matrix2d Ad;
    Ad << 1, dt, 0, 1;
    const Eigen::Vector2d Bd(0.5 * dt * dt, dt);
    EXPECT_LT((d.A - Ad).cwiseAbs().maxCoeff(), 1e-15 * std::max(1.0, dt)) << "dt " << dt;
    EXPECT_LT((d.B - Bd).cwiseAbs().maxCoeff(), 1e-15 * std::max(1.0, dt * dt)) << "dt " << dt;
  }
  }
}

TEST(Zoh, QuadrotorSystemsMatchTaylorSeriesAtSeveralStepsOnEveryInstructionSet) {
  const EachKernelIsa each;
  for (const KernelIsa isa : each.isas) {
  SCOPED_TRACE(toString(isa));
  setKernelIsa(isa);
  std::mt19937_64 rng(42);
  std::normal_distribution<double> normal(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 40; ++i) {
    const Quat q = quat::exp(Vec3(normal(rng), normal(rng), normal(rng)));
    const State x = makeState(Vec3(normal(rng), normal(rng), normal(rng)), q, 3.0 * Vec3(normal(rng), normal(rng), normal(rng)));
    const Input u = makeInput(3.0 * Vec3(normal(rng), normal(rng), normal(rng)), 2.0 + 16.0 * std::abs(normal(rng)) / 3.0);
    const double dt = std::array<double, 4>{0.001, 0.01, 0.05, 0.3}[i % 4];
    const Linearization lin = linearize(x, u);

    const double error_full = zohErrorAgainstTaylor<10, 4>(lin.A, lin.B, dt);
    const TangentSystem tangent = projectToTangent(lin, tangentBasis(q), LqrParams().q_diag);
    const double error_r = zohErrorAgainstTaylor<9, 4>(tangent.A, tangent.B, dt);
    worst = std::max({worst, error_full, error_r});
    EXPECT_LT(error_full, 1e-14) << "case " << i << " dt " << dt;
    EXPECT_LT(error_r, 1e-14) << "case " << i << " dt " << dt;
  }
  std::cout << toString(isa) << ": worst relative ZOH error vs long-double Taylor series: " << worst << "\n";
  RecordProperty(std::string("worst_relative_error_") + toString(isa), std::to_string(worst));
  }
}

TEST(Zoh, TangentDiscretizationIsTheProjectionOfTheFullOne) {
  // The norm direction never feeds back, so E^T Ad10 E = Ad9 and E^T Bd10 = Bd9 exactly.
  const Quat q = quat::exp(Vec3(0.4, -0.7, 1.3));
  const State x = makeState(Vec3(1, 2, 3), q, Vec3(2, -1, 0.5));
  const Input u = makeInput(Vec3(4, -6, 3), 15.0);
  const Linearization lin = linearize(x, u);
  const TangentBasis E = tangentBasis(q);
  const TangentSystem tangent = projectToTangent(lin, E, LqrParams().q_diag);
  const DiscreteSystem<10, 4> full = discretizeZoh<10, 4>(lin.A, lin.B, 0.01);
  const DiscreteSystem<9, 4> reduced = discretizeZoh<9, 4>(tangent.A, tangent.B, 0.01);
  EXPECT_LT((E.transpose() * full.A * E - reduced.A).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((E.transpose() * full.B - reduced.B).cwiseAbs().maxCoeff(), 1e-14);
}

}  // namespace
}  // namespace sdlqr
