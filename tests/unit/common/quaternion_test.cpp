#include <gtest/gtest.h>

#include <random>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr {
namespace {

Quat randomUnit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  return Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
}

TEST(Quaternion, MatricesAgreeWithMultiplication) {
  std::mt19937_64 rng(1);
  for (int i = 0; i < 100; ++i) {
    const Quat a = randomUnit(rng), b = randomUnit(rng);
    EXPECT_LT((quat::leftMatrix(a) * b - quat::multiply(a, b)).norm(), 1e-14);   // eq. (4)
    EXPECT_LT((quat::rightMatrix(b) * a - quat::multiply(a, b)).norm(), 1e-14);  // eq. (4)
  }
}

TEST(Quaternion, Equation9RelatesMultiplicationMatricesToTheRotation) {
  std::mt19937_64 rng(2);
  for (int i = 0; i < 100; ++i) {
    const Quat q = randomUnit(rng);
    const Mat4 product = quat::rightMatrix(q).transpose() * quat::leftMatrix(q);
    EXPECT_NEAR(product(0, 0), 1.0, 1e-14);
    EXPECT_LT((product.block<3, 3>(1, 1) - quat::rotationMatrix(q)).norm(), 1e-14);
  }
}

TEST(Quaternion, RotationMatchesSandwichProduct) {
  std::mt19937_64 rng(3);
  for (int i = 0; i < 100; ++i) {
    const Quat q = randomUnit(rng);
    const Vec3 v(1.0, -2.0, 0.5);
    const Quat sandwich = quat::multiply(quat::multiply(q, quat::pure(v)), quat::conjugate(q));
    EXPECT_LT((quat::rotate(q, v) - sandwich.tail<3>()).norm(), 1e-14);
    EXPECT_LT((quat::bodyZ(q) - quat::rotationMatrix(q).col(2)).norm(), 1e-14);
  }
}

TEST(Quaternion, ExpAndLogAreInverse) {
  std::mt19937_64 rng(4);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    Vec3 v(n(rng), n(rng), n(rng));
    if (v.norm() > 3.0) v *= 3.0 / v.norm();
    EXPECT_LT((quat::log(quat::exp(v)) - v).norm(), 1e-12);
  }
  EXPECT_LT(quat::log(quat::exp(Vec3(1e-10, 0, 0))).norm() - 1e-10, 1e-20);
}

TEST(Quaternion, YawTiltAndHemisphere) {
  EXPECT_NEAR(quat::yaw(quat::fromYaw(2.5)), 2.5, 1e-14);
  EXPECT_NEAR(quat::tilt(quat::exp(Vec3(0.5, 0.0, 0.0))), 0.5, 1e-12);
  const Quat q = quat::fromYaw(1.0);
  EXPECT_GT(quat::sameHemisphere(-q, q).dot(q), 0.0);
  EXPECT_LT((quat::boxMinus(quat::multiply(q, quat::exp(Vec3(0.1, 0.2, 0.3))), q) - Vec3(0.1, 0.2, 0.3)).norm(),
            1e-12);
}

}  // namespace
}  // namespace sdlqr
