// Reference selection of the controller: take-off ramp, held setpoints (the paper's reference
// jumps), trajectories, landing.

#include <gtest/gtest.h>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/reference_generator.hpp"
#include "controller_test_commands.hpp"
#include "sdlqr/math/model.hpp"

namespace sdlqr::controller {
namespace {

using test::command;

StateEstimate referenceEstimate(double t, const Vec3& p, const Vec3& v = Vec3::Zero(),
                         EstimatorStatus status = EstimatorStatus::kOk) {
  StateEstimate e;
  e.utime = static_cast<int64_t>(t * 1e6);
  e.position = p;
  e.velocity = v;
  e.status = status;
  return e;
}

TEST(ReferenceGenerator, IdleUntilTakeoffAndAnInitialisedEstimate) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  EXPECT_FALSE(gen.update(referenceEstimate(0.0, Vec3::Zero()), ref));
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1.5)));
  EXPECT_FALSE(gen.update(referenceEstimate(0.01, Vec3::Zero(), Vec3::Zero(), EstimatorStatus::kInitializing), ref));
  EXPECT_TRUE(gen.update(referenceEstimate(0.02, Vec3(0.5, -0.5, 0.0)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kTakeoff);
  EXPECT_EQ(position(ref.x), Vec3(0.5, -0.5, 0.0));
  EXPECT_EQ(ref.u, makeInput(Vec3::Zero(), kDefaultGravity));
  EXPECT_EQ(ref.mode, ReferenceMode::kSetpoint);
}

TEST(ReferenceGenerator, TakeoffRampClimbsAtTheTakeoffSpeedThenHolds) {
  ControllerParams params;
  params.takeoff_speed = 0.5;
  ReferenceGenerator gen(params, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1.0)));
  gen.update(referenceEstimate(0.0, Vec3::Zero()), ref);
  for (int i = 1; i <= 100; ++i) gen.update(referenceEstimate(0.01 * i, Vec3::Zero()), ref);  // 1 s
  EXPECT_NEAR(ref.x[2], 0.5, 1e-9);
  EXPECT_NEAR(velocity(ref.x)[2], 0.5, 1e-12);
  for (int i = 101; i <= 300; ++i) gen.update(referenceEstimate(0.01 * i, Vec3::Zero()), ref);
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
  EXPECT_NEAR(ref.x[2], 1.0, 1e-12);
  EXPECT_EQ(velocity(ref.x), Vec3::Zero());
}

TEST(ReferenceGenerator, GotoJumpsTheSetpointAtOnceWithItsYaw) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1.0)));
  gen.update(referenceEstimate(0.0, Vec3::Zero()), ref);
  gen.handleCommand(command(CommandType::kGoto, Vec3(1, 2, 3), 0.7));
  ASSERT_TRUE(gen.update(referenceEstimate(0.01, Vec3::Zero()), ref));
  EXPECT_EQ(position(ref.x), Vec3(1, 2, 3));
  EXPECT_NEAR(quat::yaw(orientation(ref.x)), 0.7, 1e-12);
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
}

TEST(ReferenceGenerator, GotoWhileIdleIsIgnored) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kGoto, Vec3(1, 2, 3)));
  EXPECT_FALSE(gen.update(referenceEstimate(0.01, Vec3::Zero()), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kIdle);
}

TEST(ReferenceGenerator, LandingDescendsBelowTheGroundAndGoesIdleOnceResting) {
  ControllerParams params;
  params.landing_speed = 0.5;
  params.landed_time = 0.5;
  ReferenceGenerator gen(params, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1.0)));
  gen.update(referenceEstimate(0.0, Vec3::Zero()), ref);
  gen.handleCommand(command(CommandType::kGoto, Vec3(0, 0, 1.0)));
  gen.update(referenceEstimate(0.01, Vec3(0, 0, 1)), ref);
  gen.handleCommand(command(CommandType::kLand));
  // GIVEN a vehicle that follows the reference down
  double t = 0.01;
  for (int i = 0; i < 300; ++i) {
    t += 0.01;
    ASSERT_TRUE(gen.update(referenceEstimate(t, Vec3(0, 0, std::max(0.0, ref.x[2])), Vec3(0, 0, -0.5)), ref));
    EXPECT_NEAR(velocity(ref.x)[2], -0.5, 1e-12) << "the landing reference keeps asking to descend";
  }
  EXPECT_NEAR(ref.x[2], -params.landing_undershoot, 1e-9);
  // WHEN it rests on the ground THEN the controller goes idle after landed_time
  int ticks = 0;
  while (gen.update(referenceEstimate(t += 0.01, Vec3::Zero()), ref)) ++ticks;
  EXPECT_EQ(gen.phase(), FlightPhase::kIdle);
  EXPECT_NEAR(ticks, 50, 1);
}

Trajectory line(double length, int samples) {
  Trajectory traj;
  traj.tracking = ReferenceMode::kSpatial;
  for (int i = 0; i < samples; ++i) {
    TrajectorySample s;
    s.t = i * 0.1;
    s.x = makeState(Vec3(length * i / (samples - 1), 0, 1), identityQuat(), Vec3(1, 0, 0));
    s.u = makeInput(Vec3::Zero(), kDefaultGravity);
    traj.samples.push_back(s);
  }
  return traj;
}

TEST(ReferenceGenerator, TrajectoryOnlyWhileFlyingAndTrackedSpatially) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  EXPECT_FALSE(gen.setTrajectory(line(2.0, 21), 0).empty()) << "refused on the ground";
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1.0)));
  gen.update(referenceEstimate(0.0, Vec3::Zero()), ref);
  Trajectory traj = line(2.0, 21);
  traj.seq = 42;
  EXPECT_EQ(gen.setTrajectory(traj, 0), "");
  ASSERT_TRUE(gen.update(referenceEstimate(0.01, Vec3(0.55, 0.0, 1.0)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kTrajectory);
  EXPECT_EQ(ref.mode, ReferenceMode::kSpatial);
  EXPECT_EQ(ref.trajectory_seq, 42);
  EXPECT_EQ(ref.index, 6);  // between samples 5 (0.5 m) and 6 (0.6 m)
  EXPECT_NEAR(ref.gamma, 0.5, 1e-9);
  EXPECT_NEAR(ref.x[0], 0.55, 1e-12);
  // A GOTO ends tracking and holds the new setpoint.
  gen.handleCommand(command(CommandType::kGoto, Vec3(0, 0, 1)));
  ASSERT_TRUE(gen.update(referenceEstimate(0.03, Vec3(0.55, 0.0, 1.0)), ref));
  EXPECT_EQ(ref.mode, ReferenceMode::kSetpoint);
  EXPECT_FALSE(gen.tracker().loaded());
}

TEST(ReferenceGenerator, TrackingModeSwitchKeepsThePlace) {
  ReferenceGenerator gen(ControllerParams{}, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1.0)));
  gen.update(referenceEstimate(0.0, Vec3::Zero()), ref);
  ASSERT_EQ(gen.setTrajectory(line(2.0, 21), 0), "");
  ASSERT_TRUE(gen.update(referenceEstimate(0.5, Vec3(0.95, 0.0, 1.0)), ref));
  const double before = ref.x[0];
  EXPECT_TRUE(gen.setTrackingMode(ReferenceMode::kTemporal, 500000));
  ASSERT_TRUE(gen.update(referenceEstimate(0.5, Vec3(0.95, 0.0, 1.0)), ref));
  EXPECT_EQ(ref.mode, ReferenceMode::kTemporal);
  EXPECT_NEAR(ref.x[0], before, 1e-9);
  EXPECT_FALSE(gen.setTrackingMode(ReferenceMode::kSetpoint, 500000));
}

}  // namespace
}  // namespace sdlqr::controller
