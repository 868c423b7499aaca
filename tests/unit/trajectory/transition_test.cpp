// Entries into and exits from a trajectory (transition.hpp): the polynomial meets both ends to the
// third derivative, the search returns a transition every point of which is within the limits,
// the flat state of a reference is the one its inputs produce, and no allocation is made.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "agile_vehicle.hpp"
#include "allocation_counter.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::trajectory {
namespace {

constexpr double kGravity = 9.81;

FlatState restAt(const Vec3& p) {
  FlatState s;
  s.position = p;
  return s;
}

Trajectory circleAt(double speed, double radius) {
  ClosedPathSpec spec;
  spec.speed = speed;
  spec.size = radius;
  spec.center = Vec3(0.0, 0.0, 1.5);
  return sampleClosedPath(spec, kGravity);
}

TEST(Transition, MeetsBothEndsToTheThirdDerivative) {
  FlatState from, to;
  from.position = Vec3(0.1, -0.2, 1.0);
  from.velocity = Vec3(0.5, 0.0, -0.1);
  from.acceleration = Vec3(0.0, 1.0, 0.2);
  from.jerk = Vec3(0.3, 0.0, 0.0);
  to.position = Vec3(1.5, 0.0, 1.5);
  to.velocity = Vec3(0.0, 3.0, 0.0);
  to.acceleration = Vec3(-6.0, 0.0, 0.0);
  to.jerk = Vec3(0.0, -12.0, 0.0);
  to.yaw = 0.4;
  const Transition t = Transition::between(from, to, 2.5);
  const FlatOutput a = t.at(0.0), b = t.at(2.5);
  EXPECT_LT((a.position - from.position).norm(), 1e-12);
  EXPECT_LT((a.velocity - from.velocity).norm(), 1e-12);
  EXPECT_LT((a.acceleration - from.acceleration).norm(), 1e-12);
  EXPECT_LT((a.jerk - from.jerk).norm(), 1e-12);
  EXPECT_LT((b.position - to.position).norm(), 1e-9);
  EXPECT_LT((b.velocity - to.velocity).norm(), 1e-9);
  EXPECT_LT((b.acceleration - to.acceleration).norm(), 1e-9);
  EXPECT_LT((b.jerk - to.jerk).norm(), 1e-8);
  EXPECT_NEAR(a.yaw, 0.0, 1e-12);
  EXPECT_NEAR(b.yaw, 0.4, 1e-12);
  // Each derivative is the derivative of the one before (central differences, inside).
  const double h = 1e-5;
  for (double time = 0.1; time < 2.4; time += 0.37) {
    const FlatOutput m = t.at(time), l = t.at(time - h), r = t.at(time + h);
    EXPECT_LT(((r.position - l.position) / (2 * h) - m.velocity).norm(), 1e-6);
    EXPECT_LT(((r.velocity - l.velocity) / (2 * h) - m.acceleration).norm(), 1e-5);
    EXPECT_LT(((r.acceleration - l.acceleration) / (2 * h) - m.jerk).norm(), 1e-4);
    EXPECT_LT(((r.jerk - l.jerk) / (2 * h) - m.snap).norm(), 1e-3);
    EXPECT_NEAR((r.yaw - l.yaw) / (2 * h), m.yaw_rate, 1e-6);
  }
}

// The flat state of a sample is what its own inputs fly: the circle's centripetal acceleration and
// its jerk, from the attitude, thrust and body rates of the flat map.
TEST(Transition, FlatStateOfASampleIsTheMotionItsInputsProduce) {
  ClosedPathSpec spec;
  spec.speed = 3.0;
  spec.size = 1.5;
  const FlatOutput exact = closedPathAt(spec, 0.0);
  const FlatState s = flatStateAtStart(sampleClosedPath(spec, kGravity), kGravity);
  EXPECT_LT((s.position - exact.position).norm(), 1e-12);
  EXPECT_LT((s.velocity - exact.velocity).norm(), 1e-12);
  EXPECT_LT((s.acceleration - exact.acceleration).norm(), 1e-9);
  EXPECT_LT((s.jerk - exact.jerk).norm(), 1e-6);
}

// GIVEN a hover at the start of a 1.5 m circle flown at 3.25 m/s (the speed that crashed with a
// velocity-step entry) THEN the entry found keeps every grid point within thrust, omega and speed.
TEST(Transition, EntryIntoAFastCircleFromAHoverIsWithinTheLimits) {
  const LqrParams lqr;
  const TransitionParams params;
  const Trajectory circle = circleAt(3.25, 1.5);
  const FlatState to = flatStateAtStart(circle, kGravity);
  const TransitionPlan plan = planTransition(restAt(to.position), to, lqr, params);
  ASSERT_TRUE(plan.found) << describeTransition("entry", plan);
  std::cout << describeTransition("entry", plan) << "\n";
  EXPECT_TRUE(checkFeasibility(plan.transition, plan.limits, kGravity).feasible());
  EXPECT_LE(plan.report.max_body_rate, lqr.omega_max);
  EXPECT_LE(plan.report.max_thrust, lqr.c_max);
  EXPECT_GE(plan.report.min_thrust, lqr.c_min);
  // Half the duration fails a limit: the search returns (nearly) the shortest.
  const Transition faster = Transition::between(restAt(to.position), to, 0.5 * plan.transition.duration());
  EXPECT_FALSE(checkFeasibility(faster, plan.limits, kGravity).feasible());
}

TEST(Transition, StopFromSpeedEndsAtRestAheadOfTheVehicle) {
  FlatState moving;
  moving.position = Vec3(1.0, 0.0, 1.5);
  moving.velocity = Vec3(0.0, 3.0, 0.0);
  moving.acceleration = Vec3(-6.0, 0.0, 0.0);
  const TransitionPlan plan = planStop(moving, LqrParams(), TransitionParams());
  ASSERT_TRUE(plan.found) << describeTransition("stop", plan);
  const FlatOutput end = plan.transition.at(plan.transition.duration());
  EXPECT_LT(end.velocity.norm(), 1e-9);
  EXPECT_LT(end.acceleration.norm(), 1e-9);
  EXPECT_GT(end.position.y(), moving.position.y());
}

// GIVEN the paper's min-snap at 0.6 s, leaving its start at 1.35 m/s and accelerating at 4.3 m/s^2
// THEN no stop keeps within 1.2 x that speed (the acceleration must turn round first, within the
// body-rate limit, and the vehicle speeds up meanwhile) but one within the path's own 3 m/s does,
// still within input_fraction of the limits.
TEST(Transition, AStopWhereThePathAcceleratesHardIsPlannedUnderThePathsSpeed) {
  const TrajectoryParams params;
  const Trajectory minsnap = sampleTrajectory(paperMinSnapFast(params), params.sample_dt, kGravity);
  const TrajectorySample& leaving = minsnap.samples.at(6);
  ASSERT_NEAR(leaving.t, 0.6, 1e-9);
  const LqrParams lqr;
  const FlatState from = flatStateOf(leaving.x, leaving.u, 0.0, kGravity);
  const double own_bound = 1.2 * velocity(leaving.x).norm();
  EXPECT_FALSE(planStop(from, lqr, TransitionParams()).found) << "under the sample's own speed bound";
  EXPECT_FALSE(stopExists(from, lqr, TransitionParams(), 0.0));
  const TransitionPlan plan = planStop(from, lqr, TransitionParams(), peakSpeed(minsnap));
  ASSERT_TRUE(plan.found) << describeTransition("stop", plan);
  EXPECT_TRUE(stopExists(from, lqr, TransitionParams(), peakSpeed(minsnap)));
  EXPECT_GT(plan.report.max_speed, own_bound) << "it needed the path's speed";
  EXPECT_LE(plan.report.max_speed, 1.2 * 3.0);
  EXPECT_LE(plan.report.max_body_rate, 0.8 * lqr.omega_max * (1.0 + 1e-9)) << "within input_fraction";
}

// GIVEN the agile vehicle's lemniscate at 9 m/s where it pulls 28 m/s^2 into a turn THEN the stop
// needs more than input_fraction (80 %) of c_max: it is planned within the full 45 m/s^2, the
// limits the path itself is checked against. Negative: a vehicle of 40 m/s^2 has none there.
TEST(Transition, AStopFromATurnNearTheLimitsIsPlannedWithinTheFullLimits) {
  const Trajectory lemniscate = test::agileLemniscate(9.0);
  const TrajectorySample& turning = lemniscate.samples.at(60);
  LqrParams lqr = test::agileLqr(true);
  const TransitionParams params = test::agileTransitions();
  const FlatState from = flatStateOf(turning.x, turning.u, 0.0, kGravity);
  ASSERT_GT(from.acceleration.norm(), 26.0);
  const TransitionPlan plan = planStop(from, lqr, params, 9.0);
  ASSERT_TRUE(plan.found) << describeTransition("stop", plan);
  EXPECT_EQ(plan.limits.c_max, 45.0);
  EXPECT_GT(plan.report.max_thrust, 0.8 * 45.0) << "beyond input_fraction";
  EXPECT_LE(plan.report.max_thrust, 45.0);
  lqr.c_max = 40.0;
  EXPECT_FALSE(planStop(from, lqr, params, 9.0).found);
  EXPECT_FALSE(stopExists(from, lqr, params, 9.0));
}

// GIVEN a hover at the start of the agile lemniscate at 9.5 m/s THEN no entry is found within 80 %
// of the limits, and none is planned at the full limits either (an entry that finds none is refused
// and the vehicle holds: an entry flown at the limits leaves the feedback no room); the same motion
// as an exit, whose alternative is a jump, is planned within the full limits.
TEST(Transition, AnEntryIsNeverPlannedAtTheFullLimitsAnExitIs) {
  const Trajectory lemniscate = test::agileLemniscate(9.5);
  const FlatState start = flatStateAtStart(lemniscate, kGravity);
  const TransitionParams params = test::agileTransitions();
  const LqrParams lqr = test::agileLqr(true);
  const TransitionPlan entry = planTransition(restAt(start.position), start, lqr, params, 9.5, TransitionKind::kEntry);
  EXPECT_FALSE(entry.found) << describeTransition("entry", entry);
  const TransitionPlan exit = planTransition(restAt(start.position), start, lqr, params, 9.5, TransitionKind::kExit);
  ASSERT_TRUE(exit.found);
  EXPECT_EQ(exit.limits.c_max, lqr.c_max);
  EXPECT_GT(exit.report.max_thrust, 0.8 * lqr.c_max) << "it needed more than input_fraction";
}

// The check's hint (the stop's duration from the sample before, tried first) changes how much is
// computed, never the answer: over the agile lemniscate at 9 m/s on a 40 m/s^2 vehicle, where some
// samples have a stop and some have none, hinted and unhinted agree at every sample.
TEST(Transition, AStopExistsWithTheHintWhereItDoesWithout) {
  const Trajectory lemniscate = test::agileLemniscate(9.0);
  LqrParams lqr = test::agileLqr(true);
  lqr.c_max = 40.0;
  const TransitionParams params = test::agileTransitions();
  double hint = 0.0;
  int with_stop = 0, without = 0;
  for (const TrajectorySample& sample : lemniscate.samples) {
    const FlatState from = flatStateOf(sample.x, sample.u, 0.0, kGravity);
    const bool exists = stopExists(from, lqr, params, 9.0);
    EXPECT_EQ(stopExists(from, lqr, params, 9.0, hint), exists) << "t = " << sample.t;
    (exists ? with_stop : without) += 1;
  }
  EXPECT_GT(with_stop, 100);
  EXPECT_EQ(without, 11);
}

// Negative: limits no duration can meet (a thrust floor above what a hover needs) find none, and
// say so.
TEST(Transition, NoneFoundWhenTheLimitsExcludeEveryDuration) {
  LqrParams lqr;
  lqr.c_min = 12.0;
  TransitionParams params;
  params.max_duration = 4.0;
  const TransitionPlan plan = planTransition(restAt(Vec3(0, 0, 1)), restAt(Vec3(1, 0, 1)), lqr, params);
  EXPECT_FALSE(plan.found);
  EXPECT_NE(describeTransition("entry", plan).find("none within 4 s"), std::string::npos);
}

TEST(Transition, CloseEnoughNeedsEveryToleranceMet) {
  const TransitionParams params;
  const FlatState start = restAt(Vec3(0, 0, 1));
  EXPECT_TRUE(closeEnough(restAt(Vec3(0.03, 0, 1)), start, params));
  EXPECT_FALSE(closeEnough(restAt(Vec3(0.08, 0, 1)), start, params));
  FlatState moving = restAt(Vec3(0, 0, 1));
  moving.velocity = Vec3(0.2, 0, 0);
  EXPECT_FALSE(closeEnough(moving, start, params));
}

TEST(Transition, PlanningAllocatesNothing) {
  const Trajectory circle = circleAt(3.0, 1.5);
  const FlatState to = flatStateAtStart(circle, kGravity);
  const LqrParams lqr;
  const TransitionParams params;
  const sdlqr::testing::AllocationCounter allocations;
  const TransitionPlan plan = planTransition(restAt(to.position), to, lqr, params);
  const TransitionPlan stop = planStop(to, lqr, params);
  FlatState slow_and_accelerating = restAt(Vec3(0, 0, 1));  // every tier searched
  slow_and_accelerating.velocity = Vec3(1.35, 0, 0);
  slow_and_accelerating.acceleration = Vec3(4.3, 0, 0);
  const TransitionPlan slow_stop = planStop(slow_and_accelerating, lqr, params, 3.0);
  const bool exists = stopExists(slow_and_accelerating, lqr, params, 3.0);
  EXPECT_EQ(allocations.count(), 0);
  EXPECT_TRUE(plan.found && stop.found && slow_stop.found && exists);
}

}  // namespace
}  // namespace sdlqr::trajectory
