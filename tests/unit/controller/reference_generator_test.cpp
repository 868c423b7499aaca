// Reference selection of the controller: take-off ramp, held setpoints (the paper's reference
// jumps), trajectories, landing.

#include <gtest/gtest.h>

#include <limits>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/reference_generator.hpp"
#include "agile_vehicle.hpp"
#include "controller_test_commands.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"

namespace sdlqr::controller {
namespace {

using test::command;

StateEstimate referenceEstimate(double t, const Vec3& p, const Vec3& v = Vec3::Zero(),
                         EstimatorStatus status = EstimatorStatus::kOk) {
  StateEstimate e = test::estimate(t, p, status);
  e.velocity = v;
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

// Without transitions (the old steps): tracked from the first tick, left at once by a GOTO.
ControllerParams withoutTransitions() {
  ControllerParams params;
  params.transition.enabled = false;
  return params;
}

TEST(ReferenceGenerator, TrajectoryOnlyWhileFlyingAndTrackedSpatially) {
  ReferenceGenerator gen(withoutTransitions(), kDefaultGravity);
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
  ReferenceGenerator gen(withoutTransitions(), kDefaultGravity);
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

// A generator hovering at `at` (take-off, then a GOTO there), at t = 0.01 s.
ReferenceGenerator hoveringAt(const Vec3& at, const ControllerParams& params = ControllerParams{}) {
  ReferenceGenerator gen(params, kDefaultGravity);
  Reference ref;
  gen.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, at.z())));
  gen.update(referenceEstimate(0.0, at), ref);
  gen.handleCommand(command(CommandType::kGoto, at));
  gen.update(referenceEstimate(0.01, at), ref);
  return gen;
}

// GIVEN a hover 0.5 m behind the start of a path that starts at 1 m/s WHEN it is uploaded THEN the
// reference first flies the entry (mode TRANSITION, the path's seq, by the clock, from the vehicle
// at rest) and hands over to the path's first sample at its end, after which it is tracked.
TEST(ReferenceGenerator, AnEntryJoinsAPathThatStartsAtSpeed) {
  ReferenceGenerator gen = hoveringAt(Vec3(-0.5, 0, 1));
  Trajectory traj = line(2.0, 21);
  traj.seq = 7;
  ASSERT_EQ(gen.setTrajectory(traj, 10000), "");
  Reference ref;
  ASSERT_TRUE(gen.update(referenceEstimate(0.02, Vec3(-0.5, 0, 1)), ref));
  EXPECT_EQ(ref.mode, ReferenceMode::kTransition);
  EXPECT_EQ(ref.trajectory_seq, 7);
  EXPECT_NEAR(velocity(ref.x).norm(), 0.0, 1e-9) << "starts from the vehicle at rest";
  EXPECT_EQ(gen.transitions(), 1);
  const double duration = gen.transition().plan().transition.duration();
  EXPECT_GT(duration, 0.25);
  EXPECT_LE(gen.transition().plan().report.max_body_rate, LqrParams().omega_max);
  // The vehicle follows the reference exactly through the entry.
  double t = 0.02;
  while (ref.mode == ReferenceMode::kTransition) {
    t += 0.01;
    ASSERT_TRUE(gen.update(referenceEstimate(t, position(ref.x), velocity(ref.x)), ref));
  }
  EXPECT_NEAR(t - 0.02, duration, 0.011);
  EXPECT_EQ(ref.mode, ReferenceMode::kSpatial);
  EXPECT_EQ(ref.trajectory_seq, 7);
  EXPECT_LT((position(ref.x) - Vec3(0, 0, 1)).norm(), 0.05) << "tracked from the path's start";
}

// A vehicle at the start of a path that starts at rest needs no entry: tracked at once.
TEST(ReferenceGenerator, NoEntryWhereThePathStartsAtTheHover) {
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1));
  Trajectory traj = line(2.0, 21);
  for (TrajectorySample& s : traj.samples) velocity(s.x).setZero();
  ASSERT_EQ(gen.setTrajectory(traj, 10000), "");
  Reference ref;
  ASSERT_TRUE(gen.update(referenceEstimate(0.02, Vec3(0.01, 0, 1)), ref));
  EXPECT_EQ(ref.mode, ReferenceMode::kSpatial);
  EXPECT_EQ(gen.transitions(), 0);
}

// GIVEN a path tracked at 1 m/s WHEN a GOTO arrives THEN the reference brakes through an exit to
// rest at the GOTO's position (mode TRANSITION, seq -1) and holds there: no velocity step.
TEST(ReferenceGenerator, AGotoWhileTrackingExitsToRestAtTheGoto) {
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1));
  ASSERT_EQ(gen.setTrajectory(line(2.0, 21), 10000), "");
  Reference ref;
  double t = 0.01;
  while (ref.mode != ReferenceMode::kSpatial) {
    t += 0.01;
    ASSERT_TRUE(gen.update(referenceEstimate(t, position(ref.x), velocity(ref.x)), ref));
  }
  const Vec3 before = velocity(ref.x);
  gen.handleCommand(command(CommandType::kGoto, Vec3(0, 1, 1), 0.3));
  ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kExit);
  EXPECT_EQ(ref.mode, ReferenceMode::kTransition);
  EXPECT_EQ(ref.trajectory_seq, -1);
  EXPECT_LT((velocity(ref.x) - before).norm(), 0.1) << "no velocity step";
  while (gen.phase() == FlightPhase::kExit) {
    ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  }
  ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
  EXPECT_LT((position(ref.x) - Vec3(0, 1, 1)).norm(), 1e-9);
  EXPECT_NEAR(quat::yaw(orientation(ref.x)), 0.3, 1e-9);
}

// LAND while tracking: a stop first, then the landing ramp from where the vehicle stopped.
TEST(ReferenceGenerator, ALandWhileTrackingStopsThenLands) {
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1));
  ASSERT_EQ(gen.setTrajectory(line(2.0, 21), 10000), "");
  Reference ref;
  double t = 0.01;
  for (int i = 0; i < 150; ++i) ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  gen.handleCommand(command(CommandType::kLand));
  ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kExit);
  while (gen.phase() == FlightPhase::kExit) {
    ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  }
  EXPECT_EQ(gen.phase(), FlightPhase::kLanding);
  EXPECT_LT(velocity(ref.x).norm(), 1e-9) << "at rest where the stop ended";
}

// GIVEN the paper's min-snap flown by the clock (after its entry) WHEN a LAND comes as it leaves its start (1.35 m/s,
// accelerating at 4.3 m/s^2: no stop within 1.2 x that speed) THEN the reference still stops through an exit,
// planned under the path's speed, before the landing: not a jump from the path to the ramp.
TEST(ReferenceGenerator, ALandWhereThePathAcceleratesHardStillStopsFirst) {
  const trajectory::TrajectoryParams params;
  Trajectory minsnap = trajectory::sampleTrajectory(trajectory::paperMinSnapFast(params), params.sample_dt,
                                                    kDefaultGravity);
  minsnap.tracking = ReferenceMode::kTemporal;
  ReferenceGenerator gen = hoveringAt(position(minsnap.samples.front().x));
  ASSERT_EQ(gen.setTrajectory(minsnap, 10000), "");
  Reference ref;
  double t = 0.01;
  while ((ref.mode != ReferenceMode::kTemporal || velocity(ref.x).norm() < 1.3) && t < 5.0) {
    ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  }
  const double speed = velocity(ref.x).norm();
  ASSERT_NEAR(speed, 1.35, 0.05);
  const Vec3 acceleration = trajectory::flatStateOf(ref.x, ref.u, 0.0, kDefaultGravity).acceleration;
  ASSERT_GT(acceleration.dot(velocity(ref.x)) / speed, 3.5) << "speeding up hard";
  gen.handleCommand(command(CommandType::kLand));
  ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  EXPECT_EQ(gen.phase(), FlightPhase::kExit);
  EXPECT_EQ(ref.mode, ReferenceMode::kTransition);
  const trajectory::TransitionPlan& stop = gen.transition().plan();
  EXPECT_GT(stop.report.max_speed, 1.2 * speed) << "planned under the path's speed";
  EXPECT_LE(stop.report.max_speed, 1.2 * 3.0);
  while (gen.phase() == FlightPhase::kExit) {
    ASSERT_TRUE(gen.update(referenceEstimate(t += 0.01, position(ref.x), velocity(ref.x)), ref));
  }
  EXPECT_EQ(gen.phase(), FlightPhase::kLanding);
}

// Negative: a path whose samples ask beyond the limits (thrust 30 > c_max 18) is refused with the
// report, and nothing is tracked.
TEST(ReferenceGenerator, APathBeyondTheLimitsIsRefusedWithTheReport) {
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1));
  Trajectory traj = line(2.0, 21);
  traj.samples[5].u[kThrust] = 30.0;
  const std::string why = gen.setTrajectory(traj, 10000);
  EXPECT_NE(why.find("max thrust 30 > 18"), std::string::npos) << why;
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
}

// A 1.5 m circle at 4 m/s, as a generator samples it: beyond the paper's vehicle (||omega|| above 2
// rad/s; feasible up to about 3.5 m/s).
Trajectory fastCircle() {
  trajectory::ClosedPathSpec circle;
  circle.size = 1.5;
  circle.speed = 4.0;
  return trajectory::sampleClosedPath(circle, kDefaultGravity);
}

// GIVEN trajectory_beyond_limits: scale WHEN a TRAJECTORY beyond the limits arrives THEN it is flown
// time-scaled to its highest feasible speed, within the limits, and the fit is said.
TEST(ReferenceGenerator, APathBeyondTheLimitsIsFlownTimeScaledWhenTheVehicleFileSaysScale) {
  ControllerParams params;
  params.trajectory_beyond_limits = UploadBeyondLimits::kScale;
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1), params);
  ASSERT_EQ(gen.setTrajectory(fastCircle(), 10000), "");
  EXPECT_EQ(gen.phase(), FlightPhase::kTrajectory);
  EXPECT_EQ(gen.trajectoriesScaled(), 1);
  EXPECT_NE(gen.lastScaling().find("at 4 m/s the path is beyond the vehicle"), std::string::npos) << gen.lastScaling();
  const Trajectory& flown = gen.tracker().trajectory();
  const double peak = trajectory::peakSpeed(flown);
  EXPECT_GT(peak, 3.0);
  EXPECT_LT(peak, 4.0);
  LqrParams lqr;
  lqr.gravity = kDefaultGravity;
  const auto limits = trajectory::FeasibilityLimits::from(lqr, params.guard.max_speed, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(trajectory::checkFeasibility(flown, limits, kDefaultGravity).feasible());
  EXPECT_FALSE(trajectory::checkFeasibility(fastCircle(), limits, kDefaultGravity).feasible());
}

// Negative: by default (refuse) the same upload is refused with the report, nothing scaled.
TEST(ReferenceGenerator, APathBeyondTheLimitsIsRefusedByDefault) {
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1));
  const std::string why = gen.setTrajectory(fastCircle(), 10000);
  EXPECT_NE(why.find("beyond the vehicle"), std::string::npos) << why;
  EXPECT_EQ(gen.phase(), FlightPhase::kHold);
  EXPECT_EQ(gen.trajectoriesScaled(), 0);
}

// GIVEN the agile vehicle and its circle at 10.5 m/s, whose drag-free thrust is within c_max WHEN it
// arrives as a TRAJECTORY THEN with the drag modelled it is refused on the thrust the controller
// would fly (max thrust); without the drag in the model it is accepted; with
// trajectory_beyond_limits: scale it is flown at the speed feasible with the drag (issue 25).
TEST(ReferenceGenerator, WithTheRotorDragModelledAnUploadIsJudgedOnTheThrustFlown) {
  using sdlqr::test::agileCircle;
  using sdlqr::test::agileLqr;
  ControllerParams params;
  params.guard.max_speed = 20.0;
  ReferenceGenerator with_drag = hoveringAt(Vec3(3, 0, 2), params);
  with_drag.setLimits(agileLqr(true));
  const std::string why = with_drag.setTrajectory(agileCircle(10.5), 10000);
  EXPECT_NE(why.find("max thrust"), std::string::npos) << why;
  EXPECT_EQ(with_drag.phase(), FlightPhase::kHold);

  ReferenceGenerator without = hoveringAt(Vec3(3, 0, 2), params);
  without.setLimits(agileLqr(false));
  EXPECT_EQ(without.setTrajectory(agileCircle(10.5), 10000), "");

  params.trajectory_beyond_limits = UploadBeyondLimits::kScale;
  ReferenceGenerator scaled = hoveringAt(Vec3(3, 0, 2), params);
  scaled.setLimits(agileLqr(true));
  ASSERT_EQ(scaled.setTrajectory(agileCircle(10.5), 10000), "");
  EXPECT_EQ(scaled.trajectoriesScaled(), 1);
  const double peak = trajectory::peakSpeed(scaled.tracker().trajectory());
  EXPECT_LT(peak, 10.45);
  EXPECT_GT(peak, 9.5);
}

// GIVEN the vehicle tilted 80 degrees while tracking WHEN the guard sees it THEN the trajectory is
// aborted into a recovery: the reference is the vehicle itself, level and at rest, until it is
// level and slow; then it holds there.
TEST(ReferenceGenerator, AGuardTripRecoversThenHoldsWhereTheVehicleStopped) {
  ReferenceGenerator gen = hoveringAt(Vec3(0, 0, 1), withoutTransitions());
  ASSERT_EQ(gen.setTrajectory(line(2.0, 21), 10000), "");
  Reference ref;
  ASSERT_TRUE(gen.update(referenceEstimate(0.02, Vec3(0, 0, 1)), ref));
  StateEstimate tilted = referenceEstimate(0.03, Vec3(0.2, 0.1, 1), Vec3(2, 0, 0));
  tilted.orientation = Quat(std::cos(0.5 * 1.4), std::sin(0.5 * 1.4), 0, 0);  // 80 degrees of roll
  ASSERT_TRUE(gen.update(tilted, ref));
  EXPECT_EQ(gen.guardAborts(), 1);
  EXPECT_EQ(gen.lastGuardTrip(), trajectory::GuardTrip::kTilt);
  EXPECT_TRUE(gen.recovering());
  EXPECT_EQ(ref.mode, ReferenceMode::kSetpoint);
  EXPECT_EQ(position(ref.x), Vec3(0.2, 0.1, 1)) << "the reference is the vehicle itself";
  EXPECT_EQ(velocity(ref.x), Vec3::Zero());
  ASSERT_TRUE(gen.update(referenceEstimate(0.5, Vec3(0.6, 0.1, 1.1), Vec3(0.1, 0, 0)), ref));
  EXPECT_FALSE(gen.recovering());
  EXPECT_EQ(position(ref.x), Vec3(0.6, 0.1, 1.1)) << "held where it stopped";
}

}  // namespace
}  // namespace sdlqr::controller
