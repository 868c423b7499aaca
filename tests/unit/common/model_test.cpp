// The analytic Jacobians of eq. (16)-(23), as derived in common/math/src/model.cpp, against central
// finite differences of f at random states and inputs (unit and non-unit quaternions).

#include <gtest/gtest.h>

#include <random>

#include "sdlqr/math/model.hpp"
#include "sdlqr/math/quaternion.hpp"

namespace sdlqr {
namespace {

struct RandomPoint {
  State x;
  Input u;
};

// |omega| up to 10 rad/s, c in 2..18, quaternion norm 1 (half the draws) or in 0.5..2.
RandomPoint drawPoint(std::mt19937_64& rng, bool unit_quaternion) {
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  RandomPoint point;
  Quat q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  if (!unit_quaternion) q *= 0.5 + 1.5 * uniform(rng);
  Vec3 omega(normal(rng), normal(rng), normal(rng));
  omega *= 10.0 * uniform(rng) / omega.norm();
  point.x = makeState(Vec3(normal(rng), normal(rng), normal(rng)) * 3.0, q,
                      Vec3(normal(rng), normal(rng), normal(rng)) * 5.0);
  point.u = makeInput(omega, 2.0 + 16.0 * uniform(rng));
  return point;
}

Linearization centralDifferences(const State& x, const Input& u, const RotorDrag& drag = {}) {
  const double h = 1e-6;
  const double g = kDefaultGravity;
  Linearization fd;
  for (int j = 0; j < kStateDim; ++j) {
    State plus = x, minus = x;
    plus[j] += h;
    minus[j] -= h;
    fd.A.col(j) = (dynamics(plus, u, g, drag) - dynamics(minus, u, g, drag)) / (2.0 * h);
  }
  for (int j = 0; j < kInputDim; ++j) {
    Input plus = u, minus = u;
    plus[j] += h;
    minus[j] -= h;
    fd.B.col(j) = (dynamics(x, plus, g, drag) - dynamics(x, minus, g, drag)) / (2.0 * h);
  }
  return fd;
}

// The agile vehicle's published drag (config/agile752.yaml), z unlike x and y so that the attitude
// terms do not cancel.
RotorDrag agileDrag() {
  RotorDrag drag;
  drag.coefficients = Vec3(0.69, 0.69, 1.34);
  return drag;
}

TEST(Model, JacobiansMatchCentralFiniteDifferencesAt2000RandomPoints) {
  std::mt19937_64 rng(20261122);
  double worst_a = 0.0, worst_b = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const RandomPoint p = drawPoint(rng, i % 2 == 0);
    const Linearization analytic = linearize(p.x, p.u);
    const Linearization fd = centralDifferences(p.x, p.u);
    // Central differences with h = 1e-6 are accurate to ~1e-8 at these magnitudes (|c| <= 18).
    const double scale = 1.0 + fd.A.cwiseAbs().maxCoeff();
    const double err_a = (analytic.A - fd.A).cwiseAbs().maxCoeff() / scale;
    const double err_b = (analytic.B - fd.B).cwiseAbs().maxCoeff() / scale;
    worst_a = std::max(worst_a, err_a);
    worst_b = std::max(worst_b, err_b);
    ASSERT_LT(err_a, 1e-7) << "A mismatch at point " << i << "\nanalytic\n" << analytic.A << "\nfd\n" << fd.A;
    ASSERT_LT(err_b, 1e-7) << "B mismatch at point " << i << "\nanalytic\n" << analytic.B << "\nfd\n" << fd.B;
  }
  RecordProperty("worst_relative_error_A", std::to_string(worst_a));
  RecordProperty("worst_relative_error_B", std::to_string(worst_b));
}

// The rotor drag's terms (issue 25): A's velocity and attitude columns and B's thrust column
// (through the rotor speed s(c) = sqrt(c / g)) against central differences of f with drag, at the
// same random points (speeds up to ~15 m/s), with x and y drag unequal too.
TEST(Model, RotorDragJacobiansMatchCentralFiniteDifferences) {
  std::mt19937_64 rng(20261205);
  RotorDrag unequal = agileDrag();
  unequal.coefficients.y() = 0.3;
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const RandomPoint p = drawPoint(rng, i % 2 == 0);
    const RotorDrag& drag = i % 4 < 2 ? agileDrag() : unequal;
    const Linearization analytic = linearize(p.x, p.u, 1.0, drag);
    const Linearization fd = centralDifferences(p.x, p.u, drag);
    const double scale = 1.0 + fd.A.cwiseAbs().maxCoeff();
    const double err = std::max((analytic.A - fd.A).cwiseAbs().maxCoeff(), (analytic.B - fd.B).cwiseAbs().maxCoeff()) / scale;
    worst = std::max(worst, err);
    ASSERT_LT(err, 1e-7) << "point " << i << "\nA\n" << analytic.A << "\nfd\n" << fd.A << "\nB\n" << analytic.B
                         << "\nfd\n" << fd.B;
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  // The terms are there: the drag-free Jacobians miss them by far more than the tolerance.
  std::mt19937_64 again(20261205);
  const RandomPoint p = drawPoint(again, true);
  const Linearization fd = centralDifferences(p.x, p.u, agileDrag());
  EXPECT_GT((linearize(p.x, p.u).A - fd.A).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_GT((linearize(p.x, p.u).B - fd.B).cwiseAbs().maxCoeff(), 1e-3);
}

// At hover thrust the drag is -R D R^T v (s = 1); it vanishes with the thrust; none leaves f as it was.
TEST(Model, RotorDragScalesWithRotorSpeedAndNoneIsThePapersModel) {
  const Quat q = quat::exp(Vec3(0.3, -0.2, 0.8));
  const Vec3 v(4.0, -2.0, 1.0);
  const Mat3 r = quat::rotationMatrix(q);
  const Vec3 at_hover = rotorDragAcceleration(q, v, kDefaultGravity, agileDrag());
  EXPECT_LT((at_hover + r * agileDrag().coefficients.cwiseProduct(r.transpose() * v)).norm(), 1e-12);
  EXPECT_LT((rotorDragAcceleration(q, v, 4.0 * kDefaultGravity, agileDrag()) - 2.0 * at_hover).norm(), 1e-12);
  EXPECT_EQ(rotorDragAcceleration(q, v, 0.0, agileDrag()).norm(), 0.0);
  const State x = makeState(Vec3(1, 2, 3), q, v);
  const Input u = makeInput(Vec3(0.5, -1.0, 0.2), 14.0);
  EXPECT_EQ(dynamics(x, u, kDefaultGravity, RotorDrag{}), dynamics(x, u));
  EXPECT_EQ(linearize(x, u, 1.0, RotorDrag{}).A, linearize(x, u).A);
}

TEST(Model, PrintedEquation21WouldFailTheCheck) {
  // Guards the test itself: the paper's printed dq_dot/domega (eq. 21) must be caught.
  const State x = makeState(Vec3::Zero(), quat::exp(Vec3(0.3, -0.5, 0.9)), Vec3::Zero());
  const Input u = makeInput(Vec3(1.0, -2.0, 0.5), 9.81);
  const Quat q = orientation(x);
  Eigen::Matrix<double, 4, 3> printed;
  printed << -q[1], -q[2], -q[3],
              q[0], -q[3], -q[2],
              q[3],  q[0],  q[1],
             -q[2],  q[1],  q[0];
  printed *= 0.5;
  const Linearization fd = centralDifferences(x, u);
  EXPECT_GT((printed - fd.B.block<4, 3>(kQuat, kRate)).cwiseAbs().maxCoeff(), 0.1);
  EXPECT_LT((linearize(x, u).B.block<4, 3>(kQuat, kRate) - fd.B.block<4, 3>(kQuat, kRate)).cwiseAbs().maxCoeff(),
            1e-8);
}

TEST(Model, HoverIsAnEquilibrium) {
  const State x = makeState(Vec3(1, 2, 3), identityQuat(), Vec3::Zero());
  const Input u = makeInput(Vec3::Zero(), kDefaultGravity);
  EXPECT_LT(dynamics(x, u).norm(), 1e-15);
}

TEST(Model, QuaternionNormDirectionIsInTheNullSpaceOfA) {
  // The norm direction does not influence the dynamics: A [0, q, 0] = 0 (why the DARE is
  // solved on the tangent space).
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100; ++i) {
    const RandomPoint p = drawPoint(rng, true);
    State direction = State::Zero();
    orientation(direction) = orientation(p.x);
    EXPECT_LT((linearize(p.x, p.u).A * direction).norm(), 1e-12);
  }
}

TEST(Model, ScalingTheQuaternionDoesNotChangeTheDynamics) {
  State x = makeState(Vec3(0, 0, 1), quat::exp(Vec3(0.2, 0.1, -0.4)), Vec3(1, 0, 0));
  const Input u = makeInput(Vec3(0.3, 0.2, 0.1), 12.0);
  const State f_unit = dynamics(x, u);
  orientation(x) *= 3.0;
  const State f_scaled = dynamics(x, u);
  EXPECT_LT((f_unit - f_scaled).norm(), 1e-14);
}

}  // namespace
}  // namespace sdlqr
