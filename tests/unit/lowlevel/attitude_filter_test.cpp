// IMU-only attitude and vertical velocity, and the ground-contact signatures.

#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/lowlevel/attitude_filter.hpp"
#include "sdlqr/lowlevel/failsafe.hpp"
#include "sdlqr/lowlevel/ground_detector.hpp"

namespace sdlqr::lowlevel {
namespace {

constexpr double kG = 9.81;
constexpr double kDt = 0.001;
constexpr double kDeg = M_PI / 180.0;

// Specific force of a vehicle at rest with attitude q: gravity's reaction in the body frame.
Vec3 restingSpecificForce(const Quat& q) { return quat::rotateInverse(q, Vec3(0.0, 0.0, kG)); }

TEST(AttitudeFilter, StartsFromTheAccelerometersUp) {
  const Quat truth = quat::exp(Vec3(10.0 * kDeg, -5.0 * kDeg, 0.0));
  AttitudeFilter filter(AttitudeFilterParams(), kG);
  filter.update(Vec3::Zero(), restingSpecificForce(truth), kDt, true, 3.0);
  EXPECT_NEAR(quat::tilt(filter.attitude()), quat::tilt(truth), 1e-9);
  EXPECT_TRUE(quat::bodyZ(filter.attitude()).isApprox(quat::bodyZ(truth), 1e-9));
}

TEST(AttitudeFilter, IntegratesTheGyroWhenTheAccelerometerIsUnusable) {
  AttitudeFilter filter(AttitudeFilterParams(), kG);
  filter.update(Vec3::Zero(), Vec3(0.0, 0.0, kG), kDt, false, 0.0);
  for (int i = 0; i < 500; ++i) filter.update(Vec3(1.0, 0.0, 0.0), Vec3(0.0, 0.0, 2.0), kDt, false, 0.0);  // thrust only
  EXPECT_NEAR(quat::tilt(filter.attitude()), 0.5, 1e-9);
}

TEST(AttitudeFilter, LearnsGyroBiasAndLevelsAtRest) {
  const Vec3 bias(0.02, -0.015, 0.01);
  const Quat truth = quat::exp(Vec3(3.0 * kDeg, 2.0 * kDeg, 0.0));
  AttitudeFilter filter(AttitudeFilterParams(), kG);
  filter.update(bias, Vec3(0.0, 0.0, kG), kDt, true, 3.0);  // starts believing it is level
  for (int i = 0; i < 10000; ++i) filter.update(bias, restingSpecificForce(truth), kDt, true, 3.0);  // 20 time constants
  EXPECT_LT((filter.gyroBias() - bias).norm(), 1e-5);
  EXPECT_NEAR(quat::tilt(filter.attitude()), quat::tilt(truth), 0.05 * kDeg);
  EXPECT_EQ(filter.verticalVelocity(), 0.0);
  EXPECT_NEAR(filter.bodyRate(bias).norm(), 0.0, 1e-6);
}

TEST(AttitudeFilter, LearnsTheVerticalAccelerometerOffsetAtRest) {
  AttitudeFilter filter(AttitudeFilterParams(), kG);
  for (int i = 0; i < 10000; ++i) filter.update(Vec3::Zero(), Vec3(0.0, 0.0, kG + 0.1), kDt, true, 3.0);
  EXPECT_NEAR(filter.verticalAccelOffset(), 0.1, 1e-6);
  // Airborne at hover the offset no longer shows up as a climb.
  for (int i = 0; i < 1000; ++i) filter.update(Vec3::Zero(), Vec3(0.0, 0.0, kG + 0.1), kDt, false, 0.0);
  EXPECT_NEAR(filter.verticalVelocity(), 0.0, 1e-5);
}

TEST(AttitudeFilter, VerticalVelocityIntegratesAndLeaks) {
  AttitudeFilter filter(AttitudeFilterParams(), kG);
  filter.update(Vec3::Zero(), Vec3(0.0, 0.0, kG), kDt, true, 0.0);
  for (int i = 0; i < 1000; ++i) filter.update(Vec3::Zero(), Vec3(0.0, 0.0, kG + 1.0), kDt, false, 0.0);
  EXPECT_NEAR(filter.verticalVelocity(), 1.0, 1e-6);  // 1 m/s^2 for 1 s, no leak
  // Free of acceleration, a 3 s leak removes 1 - 1/e of it in 3 s.
  for (int i = 0; i < 3000; ++i) filter.update(Vec3::Zero(), Vec3(0.0, 0.0, kG), kDt, false, 3.0);
  EXPECT_NEAR(filter.verticalVelocity(), std::exp(-1.0), 2e-3);
}

TEST(GroundDetector, RestNeedsGravityAndNoRotation) {
  GroundDetector ground(GroundDetectorParams(), kG);
  for (int i = 0; i < 1000; ++i) ground.update(Vec3::Zero(), Vec3(0.0, 0.0, kG), 0.0, kDt);
  EXPECT_TRUE(ground.atRest());
  for (int i = 0; i < 1000; ++i) ground.update(Vec3::Zero(), Vec3(0.0, 0.0, kG - 1.5), kG - 1.5, kDt);
  EXPECT_FALSE(ground.atRest());  // accelerating: airborne
  for (int i = 0; i < 1000; ++i) ground.update(Vec3(0.0, 0.0, 1.0), Vec3(0.0, 0.0, kG), kG, kDt);
  EXPECT_FALSE(ground.atRest());  // rotating
}

TEST(GroundDetector, ImpactIsSpecificForceTheRotorsDoNotExplain) {
  GroundDetector ground(GroundDetectorParams(), kG);
  ground.update(Vec3::Zero(), Vec3(0.0, 0.0, 19.0), 18.0, kDt);
  EXPECT_FALSE(ground.impact());  // full thrust climb
  ground.update(Vec3::Zero(), Vec3(0.0, 0.0, 40.0), kG, kDt);
  EXPECT_TRUE(ground.impact());
}

TEST(Failsafe, LevellingRateTurnsBodyZUpWithoutYaw) {
  const Quat tilted = quat::multiply(quat::fromYaw(1.0), quat::exp(Vec3(0.3, 0.0, 0.0)));
  const Vec3 rate = levellingRate(tilted, 5.0, 10.0);
  EXPECT_NEAR(rate.x(), -1.5, 1e-9);  // undo the 0.3 rad roll at 5 /s
  EXPECT_NEAR(rate.y(), 0.0, 1e-9);
  EXPECT_EQ(rate.z(), 0.0);
  EXPECT_NEAR(levellingRate(tilted, 5.0, 1.0).norm(), 1.0, 1e-12);  // bounded
  EXPECT_EQ(levellingRate(identityQuat(), 5.0, 1.0), Vec3::Zero());
}

TEST(Failsafe, ThrustDescendsAroundHoverWithinBounds) {
  Failsafe failsafe;
  failsafe.engage();
  GroundDetector ground(GroundDetectorParams(), kG);
  ground.update(Vec3::Zero(), Vec3(0.0, 0.0, kG - 1.0), kG - 1.0, kDt);
  const FailsafeOutput at_descent_rate = failsafe.step(identityQuat(), -0.5, 9.5, ground, kDt);
  EXPECT_NEAR(at_descent_rate.thrust, 9.5, 1e-9);
  const FailsafeOutput climbing = failsafe.step(identityQuat(), 3.0, 9.5, ground, kDt);
  EXPECT_NEAR(climbing.thrust, FailsafeParams().thrust_min_ratio * 9.5, 1e-9);
  EXPECT_FALSE(climbing.touched_down);
}

}  // namespace
}  // namespace sdlqr::lowlevel
