// Carrying an estimate forward to the controller's tick: exact on the motions the model
// integrates in closed form, and the identity for a zero horizon.

#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/state_prediction.hpp"
#include "sdlqr/math/model.hpp"

namespace sdlqr::controller {
namespace {

StateEstimate level(const Vec3& p, const Vec3& v) {
  StateEstimate e;
  e.utime = 1'000'000;
  e.seq = 42;
  e.position = p;
  e.velocity = v;
  e.status = EstimatorStatus::kOk;
  return e;
}

TEST(StatePrediction, HoverThrustKeepsVelocityAndMovesPositionAlongIt) {
  const StateEstimate e = level(Vec3(1, 2, 3), Vec3(0.5, -1.0, 0.25));
  const StateEstimate p = predictEstimate(e, kDefaultGravity, e.utime + 3000, kDefaultGravity);
  EXPECT_EQ(p.utime, e.utime + 3000);
  EXPECT_EQ(p.seq, 42);
  EXPECT_NEAR((p.position - (e.position + 0.003 * e.velocity)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((p.velocity - e.velocity).norm(), 0.0, 1e-12);
}

TEST(StatePrediction, ExcessThrustAcceleratesUpQuadratically) {
  const StateEstimate e = level(Vec3::Zero(), Vec3::Zero());
  const double h = 0.004;
  const StateEstimate p = predictEstimate(e, kDefaultGravity + 2.0, e.utime + 4000, kDefaultGravity);
  EXPECT_NEAR(p.velocity.z(), 2.0 * h, 1e-12);
  EXPECT_NEAR(p.position.z(), 0.5 * 2.0 * h * h, 1e-12);
}

TEST(StatePrediction, BodyRateTurnsTheAttitudeByRateTimesHorizon) {
  StateEstimate e = level(Vec3::Zero(), Vec3::Zero());
  e.body_rate = Vec3(0, 0, 1.5);  // yaw: does not tilt the thrust axis
  const StateEstimate p = predictEstimate(e, kDefaultGravity, e.utime + 4000, kDefaultGravity);
  EXPECT_NEAR(quat::yaw(p.orientation), 1.5 * 0.004, 1e-9);
  EXPECT_NEAR(p.orientation.norm(), 1.0, 1e-15);
}

TEST(StatePrediction, ZeroOrNegativeHorizonReturnsTheEstimate) {
  const StateEstimate e = level(Vec3(1, 2, 3), Vec3(4, 5, 6));
  for (int64_t dt : {0, -1000}) {
    const StateEstimate p = predictEstimate(e, 20.0, e.utime + dt, kDefaultGravity);
    EXPECT_EQ(p.position, e.position);
    EXPECT_EQ(p.velocity, e.velocity);
  }
}

}  // namespace
}  // namespace sdlqr::controller
