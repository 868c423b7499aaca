// The feasibility check and the speed fit judge the inputs the controller flies (issue 25): with the
// model's rotor drag (lqr.model_rotor_drag) each sample's thrust and body rates are those of the
// controller's remap (drag_feedforward.hpp), so a path whose thrust is within c_max only without the
// drag is refused, `on_infeasible: scale` fits the speed the vehicle manages with it, and the entries
// and exits (transition.hpp) are planned on the same inputs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

#include "sdlqr/trajectory/drag_feedforward.hpp"
#include "sdlqr/trajectory/feasibility.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/transition.hpp"
#include "agile_vehicle.hpp"

namespace sdlqr::trajectory::drag_feasibility_test {
namespace {

constexpr double kG = 9.81;

using test::agileCircle;
using test::agileLqr;

FeasibilityLimits agileLimits(bool modelled) {
  return FeasibilityLimits::from(agileLqr(modelled), 20.0, std::numeric_limits<double>::infinity());
}

// GIVEN the 3 m circle at 10.5 m/s, whose drag-free thrust is within c_max (45 m/s^2) WHEN the model
// has the rotor drag THEN the check refuses it on max thrust, with the largest thrust the controller's
// remap flies; without the drag in the model (the switch off) the same vehicle accepts it.
TEST(DragFeasibility, APathWithinCmaxOnlyWithoutTheDragIsRefusedOnMaxThrust) {
  const Trajectory path = agileCircle(10.5);
  const FeasibilityReport free = checkFeasibility(path, agileLimits(false), kG);
  EXPECT_TRUE(free.feasible()) << describeViolations(free, agileLimits(false));
  EXPECT_LT(free.max_thrust, 45.0);

  const FeasibilityReport with_drag = checkFeasibility(path, agileLimits(true), kG);
  EXPECT_FALSE(with_drag.max_thrust_ok);
  EXPECT_FALSE(with_drag.feasible());
  EXPECT_GT(with_drag.max_thrust, 45.0);
  EXPECT_NE(describeViolations(with_drag, agileLimits(true)).find("max thrust"), std::string::npos);

  // The thrust judged is the controller's: the remap of each sample (one computation for both).
  double flown_max = 0.0;
  for (const TrajectorySample& s : path.samples) {
    State x = s.x;
    Input u = s.u;
    compensateRotorDrag(x, u, kG, agileLqr(true).rotorDrag());
    flown_max = std::max(flown_max, u[kThrust]);
  }
  EXPECT_EQ(with_drag.max_thrust, flown_max);
}

// No drag in the model: the check is the drag-free one, bit for bit (every report field).
TEST(DragFeasibility, WithoutTheDragModelledTheReportIsTheDragFreeOne) {
  const Trajectory path = agileCircle(8.0);
  FeasibilityLimits none = agileLimits(false);
  ASSERT_FALSE(none.drag.active());
  const FeasibilityReport report = checkFeasibility(path, none, kG);
  double max_thrust = 0.0, max_rate = 0.0;
  for (const TrajectorySample& s : path.samples) {
    max_thrust = std::max(max_thrust, s.u[kThrust]);
    max_rate = std::max(max_rate, bodyRate(s.u).norm());
  }
  EXPECT_EQ(report.max_thrust, max_thrust);
  EXPECT_EQ(report.max_body_rate, max_rate);
}

// GIVEN the circle asked at 11.5 m/s, beyond the vehicle either way WHEN the speed is fitted (the
// generator's, and the time scaling of a given path: a CSV or an uploaded TRAJECTORY) THEN with the
// drag modelled the speed is lower than the drag-free fit, feasible with the drag, and the drag-free
// fit's speed is not.
TEST(DragFeasibility, TheScaledSpeedIsTheOneFeasibleWithTheDrag) {
  const auto generate = [](double speed) { return agileCircle(speed); };
  const SpeedFit free = fitSpeed(generate, 11.5, agileLimits(false), kG);
  const SpeedFit with_drag = fitSpeed(generate, 11.5, agileLimits(true), kG);
  std::printf("  3 m circle asked at 11.5 m/s: feasible up to %.3f m/s with the drag, %.3f m/s without\n",
              with_drag.feasible_speed, free.feasible_speed);
  ASSERT_GT(with_drag.feasible_speed, 0.0);
  EXPECT_LT(with_drag.feasible_speed, free.feasible_speed - 0.5);
  EXPECT_TRUE(checkFeasibility(with_drag.trajectory, agileLimits(true), kG).feasible());
  EXPECT_FALSE(checkFeasibility(free.trajectory, agileLimits(true), kG).max_thrust_ok);

  const SpeedFit scaled = fitSpeed(givenPathAtSpeed(agileCircle(11.5), kG), 11.5, agileLimits(true), kG);
  EXPECT_NEAR(scaled.feasible_speed, with_drag.feasible_speed, 0.02 * with_drag.feasible_speed);
  EXPECT_TRUE(checkFeasibility(scaled.trajectory, agileLimits(true), kG).feasible());
}

// The largest thrust and body rate the controller flies along a transition: each point's drag-free
// reference through its remap (flownInput), on a grid finer than the planner's.
std::pair<double, double> flownExtremes(const Transition& transition, const LqrParams& lqr) {
  double thrust = 0.0, rate = 0.0;
  constexpr int kPoints = 1000;
  for (int i = 0; i <= kPoints; ++i) {
    const FlatReference free = flatToReference(transition.at(transition.duration() * i / kPoints), kG);
    const Input u = flownInput(free.x, free.u, kG, lqr.rotorDrag());
    thrust = std::max(thrust, u[kThrust]);
    rate = std::max(rate, bodyRate(u).norm());
  }
  return {thrust, rate};
}

// The entry from a hover at the agile circle's first sample into the circle at `speed`.
TransitionPlan entryIntoAgileCircle(double speed, const LqrParams& lqr, const TransitionParams& params) {
  const FlatState start = flatStateAtStart(agileCircle(speed), kG);
  FlatState hover;
  hover.position = start.position;
  return planTransition(hover, start, lqr, params);
}

// GIVEN the agile vehicle with the rotor drag modelled WHEN the entry from a hover into the 3 m circle
// at 9 m/s and the exit from its first sample to a stop are planned THEN each, flown with the drag
// feed-forward, stays within the thrust and body rate it was planned for (planned drag-free, the
// entry flew 41.4 m/s^2 and 14.2 rad/s against its 36 and 12).
TEST(DragFeasibility, TransitionsArePlannedOnTheInputsFlownWithTheDrag) {
  const LqrParams lqr = agileLqr(true);
  const TransitionParams params;
  const FlatState start = flatStateAtStart(agileCircle(9.0), kG);
  const TransitionPlan plans[] = {entryIntoAgileCircle(9.0, lqr, params), planStop(start, lqr, params)};
  for (const TransitionPlan& plan : plans) {
    ASSERT_TRUE(plan.found) << describeTransition("transition", plan);
    EXPECT_TRUE(plan.limits.drag.active());
    const auto [thrust, rate] = flownExtremes(plan.transition, lqr);
    std::printf("  %s; flown: thrust up to %.2f m/s^2, |omega| up to %.2f rad/s\n",
                describeTransition("transition", plan).c_str(), thrust, rate);
    // Within the limits it was planned for (input_fraction of c_max and omega_max where its ends
    // allow), on a grid finer than the planner's.
    EXPECT_LE(thrust, plan.limits.c_max * (1.0 + 1e-3));
    EXPECT_LE(rate, plan.limits.omega_max * (1.0 + 1e-3));
    EXPECT_LE(plan.limits.c_max, lqr.c_max);
    EXPECT_LE(plan.limits.omega_max, lqr.omega_max);
  }
}

// GIVEN the agile vehicle and the entry from a hover into its 3 m circle WHEN gentle_fraction is 0.5
// (config/agile752.yaml) THEN at 4 m/s the entry is planned within half the limits, where the
// shortest within input_fraction (0.8, gentle_fraction no lower: one search) asks for more than
// that; at 10 m/s, where no entry within half the limits reaches the circle, it is planned within
// input_fraction as before.
TEST(DragFeasibility, AnEntryIsPlannedWithinGentleFractionWhereOneExists) {
  const LqrParams lqr = agileLqr(true);
  TransitionParams gentle;
  gentle.gentle_fraction = 0.5;
  const TransitionParams shortest;  // gentle_fraction = input_fraction = 0.8
  const TransitionPlan slow_gentle = entryIntoAgileCircle(4.0, lqr, gentle),
                       slow_shortest = entryIntoAgileCircle(4.0, lqr, shortest);
  ASSERT_TRUE(slow_gentle.found && slow_shortest.found);
  std::printf("  4 m/s: %s (gentle), %s (shortest)\n", describeTransition("entry", slow_gentle).c_str(),
              describeTransition("entry", slow_shortest).c_str());
  EXPECT_LE(slow_gentle.report.max_body_rate, 0.5 * lqr.omega_max * (1.0 + 1e-6));
  EXPECT_LE(slow_gentle.report.max_thrust, 0.5 * lqr.c_max * (1.0 + 1e-6));
  EXPECT_GT(slow_shortest.report.max_body_rate, 0.5 * lqr.omega_max) << "the shortest entry uses more";
  EXPECT_GT(slow_gentle.transition.duration(), slow_shortest.transition.duration());

  const TransitionPlan fast_gentle = entryIntoAgileCircle(10.0, lqr, gentle),
                       fast_shortest = entryIntoAgileCircle(10.0, lqr, shortest);
  ASSERT_TRUE(fast_gentle.found) << describeTransition("entry", fast_gentle);
  EXPECT_EQ(fast_gentle.transition.duration(), fast_shortest.transition.duration()) << "input_fraction's plan";
  EXPECT_EQ(fast_gentle.limits.omega_max, fast_shortest.limits.omega_max);
}

}  // namespace
}  // namespace sdlqr::trajectory::drag_feasibility_test
