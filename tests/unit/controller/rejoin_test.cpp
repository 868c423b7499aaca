// A controller restarted mid-flight (docs/architecture.md §7: "a process restarted mid-flight rejoins"): its
// first estimate shows the vehicle airborne, so it holds there instead of idling, and the
// mission's re-sent TAKEOFF / GOTO (same seq, fresh utime) restores the setpoint. Running
// controllers ignore the re-sends.

#include <gtest/gtest.h>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/reference_generator.hpp"
#include "sdlqr/controller/state_dependent_lqr.hpp"
#include "controller_test_commands.hpp"
#include "sdlqr/math/model.hpp"

namespace sdlqr::controller {
namespace {

StateEstimate rejoinEstimate(double t, const Vec3& p, double yaw = 0.0,
                         EstimatorStatus status = EstimatorStatus::kOk) {
  StateEstimate e = test::estimate(t, p, status);
  e.orientation = quat::fromYaw(yaw);
  return e;
}

Command command(CommandType type, int64_t seq, const Vec3& position = Vec3::Zero(), double yaw = 0.0) {
  Command c = test::command(type, position, yaw);
  c.seq = seq;
  c.utime = seq * 1000;
  return c;
}

TEST(Rejoin, FirstEstimateAirborneHoldsWhereTheVehicleIsWithItsYaw) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  EXPECT_FALSE(gen.update(rejoinEstimate(5.0, Vec3(0.1, 0.2, 0.7), 0.4, EstimatorStatus::kInitializing), ref));
  ASSERT_TRUE(gen.update(rejoinEstimate(5.01, Vec3(0.1, 0.2, 0.7), 0.4), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
  EXPECT_TRUE(gen.rejoined());
  EXPECT_FALSE(gen.recovering()) << "level and at rest: held where first seen, at once";
  EXPECT_EQ(position(ref.x), Vec3(0.1, 0.2, 0.7));
  EXPECT_EQ(velocity(ref.x), Vec3::Zero());
  EXPECT_NEAR(quat::yaw(orientation(ref.x)), 0.4, 1e-12);
  EXPECT_EQ(ref.mode, ReferenceMode::kSetpoint);
}

TEST(Rejoin, OnTheGroundOrBelowTheRejoinHeightStaysIdle) {
  ControllerParams params;
  params.rejoin_height = 0.2;
  ReferenceGenerator gen(params, kDefaultGravity);
  Reference ref;
  EXPECT_FALSE(gen.update(rejoinEstimate(0.0, Vec3(0, 0, 0.19)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kIdle);
  // Only the first estimate decides: climbing later without a take-off (carried by hand) is no rejoin.
  EXPECT_FALSE(gen.update(rejoinEstimate(0.01, Vec3(0, 0, 1.0)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kIdle);
}

TEST(Rejoin, ReSentTakeoffSetsTheHeightAboveTheGroundPlaneAtTheHeldPlace) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  ASSERT_TRUE(gen.update(rejoinEstimate(5.0, Vec3(0.05, -0.03, 0.62)), ref));
  gen.handleCommand(command(CommandType::kTakeoff, 1, Vec3(0, 0, 1.0)));
  ASSERT_TRUE(gen.update(rejoinEstimate(5.51, Vec3(0.05, -0.03, 0.62)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
  EXPECT_FALSE(gen.rejoined());
  EXPECT_EQ(position(ref.x), Vec3(0.05, -0.03, 1.0));
}

TEST(Rejoin, TakeoffHeardBeforeTheFirstEstimateHoldsAtThatHeight) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, 1, Vec3(0, 0, 1.5)));
  ASSERT_TRUE(gen.update(rejoinEstimate(5.0, Vec3(0.3, 0.0, 0.8)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kHold) << "no take-off ramp from mid-air";
  EXPECT_EQ(position(ref.x), Vec3(0.3, 0.0, 1.5));
}

TEST(Rejoin, ReSentGotoRestoresTheSetpoint) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  ASSERT_TRUE(gen.update(rejoinEstimate(5.0, Vec3(0.0, 0.0, 0.6)), ref));
  gen.handleCommand(command(CommandType::kGoto, 3, Vec3(1, 2, 1.2), 0.3));
  ASSERT_TRUE(gen.update(rejoinEstimate(5.01, Vec3(0.0, 0.0, 0.6)), ref));
  EXPECT_EQ(position(ref.x), Vec3(1, 2, 1.2));
  EXPECT_NEAR(quat::yaw(orientation(ref.x)), 0.3, 1e-12);
}

TEST(Rejoin, TakeoffWhileFlyingNormallyChangesNothing) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, 0, Vec3(0, 0, 1.0)));
  ASSERT_TRUE(gen.update(rejoinEstimate(0.0, Vec3::Zero()), ref));
  EXPECT_FALSE(gen.rejoined());
  gen.handleCommand(command(CommandType::kGoto, 1, Vec3(0, 0, 2.0)));
  gen.handleCommand(command(CommandType::kTakeoff, 2, Vec3(0, 0, 1.0)));
  ASSERT_TRUE(gen.update(rejoinEstimate(0.03, Vec3(0, 0, 0.5)), ref));
  EXPECT_EQ(position(ref.x), Vec3(0, 0, 2.0));
}

StateEstimate movingEstimate(double t, const Vec3& p, double roll, const Vec3& v) {
  StateEstimate e = rejoinEstimate(t, p);
  e.orientation = quat::exp(Vec3(roll, 0.0, 0.0));
  e.velocity = v;
  return e;
}

// An airborne start or a throw: tilted and moving, the reference is the vehicle itself (level, at
// rest: right it and stop it) until it is level and stopped, and the hold is set there, not at the
// place first seen.
TEST(Rejoin, ATiltedOrMovingVehicleIsRightedAndStoppedBeforeItHoldsWhereItStopped) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  ASSERT_TRUE(gen.update(movingEstimate(0.0, Vec3(0, 0, 12), 2.0, Vec3(0.5, 0, 0)), ref));
  EXPECT_TRUE(gen.recovering());
  EXPECT_EQ(position(ref.x), Vec3(0, 0, 12));
  ASSERT_TRUE(gen.update(movingEstimate(1.0, Vec3(0.4, -2.0, 8.0), 0.0, Vec3(0, -4.8, -4.7)), ref));
  EXPECT_TRUE(gen.recovering()) << "level but still moving";
  EXPECT_EQ(position(ref.x), Vec3(0.4, -2.0, 8.0));
  EXPECT_EQ(velocity(ref.x), Vec3::Zero());
  EXPECT_NEAR(quat::tilt(orientation(ref.x)), 0.0, 1e-12);
  ASSERT_TRUE(gen.update(movingEstimate(1.5, Vec3(0.5, -4.3, 6.4), 0.5, Vec3(0, -0.3, 0)), ref));
  EXPECT_TRUE(gen.recovering()) << "stopped but tilted 29 deg";
  ASSERT_TRUE(gen.update(movingEstimate(2.0, Vec3(0.53, -4.47, 6.3), 0.1, Vec3(0, 0.3, 0)), ref));
  EXPECT_FALSE(gen.recovering());
  EXPECT_EQ(position(ref.x), Vec3(0.53, -4.47, 6.3));
  ASSERT_TRUE(gen.update(movingEstimate(2.5, Vec3(0.6, -4.3, 6.5), 0.05, Vec3(0, 0.4, 0)), ref));
  EXPECT_EQ(position(ref.x), Vec3(0.53, -4.47, 6.3)) << "held, no longer following";
  // Negative: with a recovery speed below what it moves at, the same flight never holds.
  ControllerParams strict;
  strict.recovery_speed = 0.2;
  ReferenceGenerator still_recovering(strict, kDefaultGravity);
  ASSERT_TRUE(still_recovering.update(movingEstimate(0.0, Vec3(0, 0, 12), 2.0, Vec3(0.5, 0, 0)), ref));
  ASSERT_TRUE(still_recovering.update(movingEstimate(2.0, Vec3(0.53, -4.47, 6.3), 0.1, Vec3(0, 0.3, 0)), ref));
  EXPECT_TRUE(still_recovering.recovering());
}

// A re-sent TAKEOFF during the recovery names the held height; a GOTO ends the recovery at once.
TEST(Rejoin, ATakeoffKeepsItsHeightThroughTheRecoveryAndAGotoEndsIt) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  ASSERT_TRUE(gen.update(movingEstimate(0.0, Vec3(0, 0, 3), 1.0, Vec3(1, 0, 0)), ref));
  gen.handleCommand(command(CommandType::kTakeoff, 1, Vec3(0, 0, 2.0)));
  ASSERT_TRUE(gen.update(movingEstimate(0.5, Vec3(0.4, 0, 2.6), 0.5, Vec3(1, 0, 0)), ref));
  EXPECT_TRUE(gen.recovering());
  ASSERT_TRUE(gen.update(movingEstimate(1.0, Vec3(0.6, 0, 2.5), 0.0, Vec3(0.1, 0, 0)), ref));
  EXPECT_FALSE(gen.recovering());
  EXPECT_EQ(position(ref.x), Vec3(0.6, 0, 2.0));

  ReferenceGenerator told(ControllerParams{}, kDefaultGravity);
  ASSERT_TRUE(told.update(movingEstimate(0.0, Vec3(0, 0, 3), 1.0, Vec3(1, 0, 0)), ref));
  told.handleCommand(command(CommandType::kGoto, 2, Vec3(1, 1, 2)));
  ASSERT_TRUE(told.update(movingEstimate(0.5, Vec3(0.4, 0, 2.6), 0.5, Vec3(1, 0, 0)), ref));
  EXPECT_FALSE(told.recovering());
  EXPECT_EQ(position(ref.x), Vec3(1, 1, 2));
}

// The controller as a whole: the re-send of the command it handled last changes nothing; a
// restarted instance learns the setpoint from it.
TEST(Rejoin, ControllerIgnoresReSendsOfTheCommandItHandledAndARestartedOneLearnsFromThem) {
  const LqrParams lqr;
  StateDependentLqr running(lqr, ControllerParams{});
  StateDependentLqr::Tick tick;
  running.onStateEstimate(rejoinEstimate(0.0, Vec3::Zero()), tick);
  running.handleCommand(command(CommandType::kTakeoff, 0, Vec3(0, 0, 1)));
  ASSERT_TRUE(running.onStateEstimate(rejoinEstimate(0.01, Vec3::Zero()), tick));
  running.handleCommand(command(CommandType::kGoto, 1, Vec3(0.5, 0, 1)));
  ASSERT_TRUE(running.onStateEstimate(rejoinEstimate(0.02, Vec3(0, 0, 0.3)), tick));
  running.handleCommand(command(CommandType::kLand, 2));
  ASSERT_TRUE(running.onStateEstimate(rejoinEstimate(0.03, Vec3(0, 0, 0.3)), tick));
  EXPECT_EQ(running.status().phase, FlightPhase::kLanding);
  Command resend = command(CommandType::kLand, 2);
  resend.utime += 5'000'000;
  running.handleCommand(resend);
  Command goto_resend = command(CommandType::kGoto, 2, Vec3(0.5, 0, 1));  // same seq: a re-send
  running.handleCommand(goto_resend);
  ASSERT_TRUE(running.onStateEstimate(rejoinEstimate(0.04, Vec3(0, 0, 0.3)), tick));
  EXPECT_EQ(running.status().phase, FlightPhase::kLanding) << "a re-send was acted on";
  EXPECT_EQ(tick.reference.command_seq, 2);

  StateDependentLqr restarted(lqr, ControllerParams{});
  ASSERT_TRUE(restarted.onStateEstimate(rejoinEstimate(8.0, Vec3(0.02, 0.01, 0.7)), tick));
  EXPECT_EQ(restarted.status().phase, FlightPhase::kHold);
  EXPECT_EQ(position(tick.reference.x), Vec3(0.02, 0.01, 0.7));
  EXPECT_EQ(tick.command.gains_status, GainsFreshness::kFallback) << "no GAINS yet: the hover K";
  // Holding below the setpoint's altitude asks for more than hover thrust once told the height.
  Command takeoff = command(CommandType::kTakeoff, 0, Vec3(0, 0, 1));
  takeoff.utime = 8'000'000;
  restarted.handleCommand(takeoff);
  ASSERT_TRUE(restarted.onStateEstimate(rejoinEstimate(8.01, Vec3(0.02, 0.01, 0.7)), tick));
  EXPECT_EQ(position(tick.reference.x), Vec3(0.02, 0.01, 1.0));
  EXPECT_GT(tick.command.thrust, lqr.gravity);
}

}  // namespace
}  // namespace sdlqr::controller
