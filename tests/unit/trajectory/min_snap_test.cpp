#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

#include "sdlqr/trajectory/min_snap.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"

namespace sdlqr::trajectory {
namespace {

std::vector<Waypoint> someWaypoints() {
  // Uneven spacing and a sharp turn, so no derivative is trivially continuous by symmetry.
  const std::vector<Vec3> points = {Vec3(0, 0, 1), Vec3(2, 0.5, 1.5), Vec3(2.5, 3, 1), Vec3(0.5, 2, 2.5),
                                    Vec3(-1, 1, 1.2)};
  std::vector<Waypoint> out;
  for (const Vec3& p : points) out.push_back(Waypoint{p, 0.0, false});
  return out;
}

const std::vector<double> kDurations = {1.3, 2.0, 0.9, 1.7};
const std::vector<double> kPeriodicDurations = {1.3, 2.0, 0.9, 1.7, 1.1};

// Largest jump of derivative `order` across the knots, relative to the size of that derivative.
double worstKnotJump(const MinSnapTrajectory& trajectory, int order, bool include_wrap) {
  double worst = 0.0;
  const int segments = trajectory.segmentCount();
  for (const PiecewisePolynomial& axis : trajectory.axes) {
    double scale = 1.0;
    for (int k = 0; k < segments; ++k) scale = std::max(scale, std::abs(axis.evaluateInSegment(k, 0.0, order)));
    const int knots = include_wrap ? segments : segments - 1;
    for (int k = 0; k < knots; ++k) {
      const double left = axis.evaluateInSegment(k, 1.0, order);
      const double right = axis.evaluateInSegment((k + 1) % segments, 0.0, order);
      worst = std::max(worst, std::abs(left - right) / scale);
    }
  }
  return worst;
}

TEST(MinSnap, ContinuousUpToSnapAtInteriorWaypoints) {
  const MinSnapTrajectory trajectory = solveMinSnap(someWaypoints(), kDurations, false);
  for (int order = 0; order <= 4; ++order) {
    const double jump = worstKnotJump(trajectory, order, false);
    std::cout << "  derivative " << order << ": largest relative jump at a knot " << jump << "\n";
    EXPECT_LT(jump, 1e-12) << "order " << order;
  }
}

TEST(MinSnap, OptimumIsTheC6Spline) {
  // Euler-Lagrange of the snap cost: the optimum is C^6. Only C^4 is imposed, so continuous 5th
  // and 6th derivatives show that the solve found the minimum, not just a feasible point.
  const MinSnapTrajectory open = solveMinSnap(someWaypoints(), kDurations, false);
  const MinSnapTrajectory closed = solveMinSnap(someWaypoints(), kPeriodicDurations, true);
  for (int order = 5; order <= 6; ++order) {
    std::cout << "  derivative " << order << ": open " << worstKnotJump(open, order, false) << ", periodic "
              << worstKnotJump(closed, order, true) << "\n";
    EXPECT_LT(worstKnotJump(open, order, false), 1e-8);
    EXPECT_LT(worstKnotJump(closed, order, true), 1e-8);
  }
}

TEST(MinSnap, PeriodicIsContinuousAcrossTheWrap) {
  const MinSnapTrajectory trajectory = solveMinSnap(someWaypoints(), kPeriodicDurations, true);
  for (int order = 0; order <= 4; ++order) EXPECT_LT(worstKnotJump(trajectory, order, true), 1e-12) << order;
  // Not at rest: a periodic path keeps moving through its first waypoint.
  EXPECT_GT(trajectory.evaluate(0.0).velocity.norm(), 0.1);
}

TEST(MinSnap, HitsEveryWaypointExactly) {
  const std::vector<Waypoint> waypoints = someWaypoints();
  for (bool periodic : {false, true}) {
    const MinSnapTrajectory trajectory = solveMinSnap(waypoints, periodic ? kPeriodicDurations : kDurations, periodic);
    for (std::size_t j = 0; j < waypoints.size(); ++j) {
      const double t = j < static_cast<std::size_t>(trajectory.segmentCount()) ? trajectory.axes[0].segmentStart(j)
                                                                                 : trajectory.duration();
      EXPECT_LT((trajectory.evaluate(t).position - waypoints[j].position).norm(), 1e-12) << "waypoint " << j;
    }
    if (periodic) {
      EXPECT_LT((trajectory.evaluate(trajectory.duration()).position - waypoints[0].position).norm(), 1e-12);
    }
  }
}

TEST(MinSnap, StartsAndEndsAtRest) {
  const MinSnapTrajectory trajectory = solveMinSnap(someWaypoints(), kDurations, false);
  for (double t : {0.0, trajectory.duration()}) {
    const FlatOutput f = trajectory.evaluate(t);
    EXPECT_LT(f.velocity.norm(), 1e-12) << t;
    EXPECT_LT(f.acceleration.norm(), 1e-12) << t;
    EXPECT_LT(f.jerk.norm(), 1e-12) << t;
  }
  // Snap is left free at the ends (that is what makes the optimum unique and smooth).
  EXPECT_GT(trajectory.evaluate(0.0).snap.norm(), 1e-3);
}

TEST(MinSnap, LowerSnapCostThanPerturbedFeasibleAlternatives) {
  const MinSnapTrajectory optimum = solveMinSnap(someWaypoints(), kDurations, false);
  const PiecewisePolynomial& axis = optimum.axes[0];
  const int nodes = axis.segmentCount() + 1;
  Eigen::MatrixXd derivatives(nodes, 5);
  for (int j = 0; j < nodes; ++j) {
    const int k = std::min(j, axis.segmentCount() - 1);
    for (int order = 0; order < 5; ++order) derivatives(j, order) = axis.evaluateInSegment(k, j == nodes - 1 ? 1.0 : 0.0, order);
  }
  const double best = axis.squaredDerivativeIntegral(4);
  // Rebuilding from the optimum's own node derivatives reproduces it.
  EXPECT_NEAR(fromNodeDerivatives(derivatives, kDurations, false).squaredDerivativeIntegral(4), best, 1e-9 * best);

  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  double smallest_increase = INFINITY;
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::MatrixXd perturbed = derivatives;
    // Only the free entries: interior velocity..snap, end snap. Positions and rest conditions stay.
    for (int j = 0; j < nodes; ++j) {
      for (int order = (j == 0 || j == nodes - 1) ? 4 : 1; order < 5; ++order) {
        perturbed(j, order) += 0.01 * noise(rng) * std::max(1.0, std::abs(derivatives(j, order)));
      }
    }
    const double cost = fromNodeDerivatives(perturbed, kDurations, false).squaredDerivativeIntegral(4);
    EXPECT_GT(cost, best) << "trial " << trial;
    smallest_increase = std::min(smallest_increase, cost - best);
  }
  std::cout << "  optimal snap cost (x) " << best << ", smallest increase over 200 perturbations " << smallest_increase
            << "\n";
}

TEST(MinSnap, UniformTimeScalingIsMonotoneAndExact) {
  const MinSnapTrajectory base = solveMinSnap(someWaypoints(), kDurations, false);
  double previous_speed = INFINITY;
  const double base_speed = maxSpeed(base, 1e-3);
  for (double s : {0.5, 0.8, 1.0, 1.5, 2.0, 3.0}) {
    const MinSnapTrajectory scaled = base.timeScaled(s);
    const double speed = maxSpeed(scaled, 1e-3);
    EXPECT_LT(speed, previous_speed) << "scale " << s;
    EXPECT_NEAR(speed * s, base_speed, 1e-9 * base_speed);
    EXPECT_NEAR(scaled.snapCost() * std::pow(s, 7), base.snapCost(), 1e-9 * base.snapCost());
    previous_speed = speed;
    // The scaled trajectory is the optimum for the scaled durations (scale invariance).
    std::vector<double> durations = kDurations;
    for (double& d : durations) d *= s;
    const MinSnapTrajectory resolved = solveMinSnap(someWaypoints(), durations, false);
    for (double f : {0.1, 0.37, 0.5, 0.82}) {
      const double t = f * scaled.duration();
      EXPECT_LT((resolved.evaluate(t).position - scaled.evaluate(t).position).norm(), 1e-9);
      EXPECT_LT((resolved.evaluate(t).velocity - scaled.evaluate(t).velocity).norm(), 1e-9);
    }
  }
}

// The paper's trajectories as flown (time allocation and v_max scaling included): C^4 at every
// waypoint, each waypoint hit, at rest at both ends, top speed exactly v_max.
TEST(MinSnap, PaperTrajectoriesAsFlownAreContinuousUpToSnapAndHitTheirWaypoints) {
  const TrajectoryParams params;
  for (const double v_max : {params.fast_v_max, params.slow_v_max}) {
    const MinSnapTrajectory trajectory = paperMinSnap(v_max, params);
    const std::vector<Waypoint> waypoints = paperPathWaypoints(params);
    ASSERT_EQ(static_cast<std::size_t>(trajectory.segmentCount()) + 1, waypoints.size());
    for (int order = 0; order <= 4; ++order) {
      const double jump = worstKnotJump(trajectory, order, false);
      std::cout << "  v_max " << v_max << ": derivative " << order << " largest relative jump " << jump << "\n";
      EXPECT_LT(jump, 1e-10) << "v_max " << v_max << " order " << order;
    }
    for (std::size_t j = 0; j < waypoints.size(); ++j) {
      const double t = j < static_cast<std::size_t>(trajectory.segmentCount()) ? trajectory.axes[0].segmentStart(j)
                                                                                 : trajectory.duration();
      EXPECT_LT((trajectory.evaluate(t).position - waypoints[j].position).norm(), 1e-9) << "waypoint " << j;
    }
    for (double t : {0.0, trajectory.duration()}) EXPECT_LT(trajectory.evaluate(t).velocity.norm(), 1e-9);
    double top = 0.0;
    for (double t = 0.0; t <= trajectory.duration(); t += 1e-3) top = std::max(top, trajectory.evaluate(t).velocity.norm());
    EXPECT_LE(top, v_max * (1.0 + 1e-9));
    EXPECT_GT(top, v_max * 0.999);
  }
}

TEST(MinSnap, GeneratedTrajectoryKeepsVmaxOnAFineGrid) {
  for (bool periodic : {false, true}) {
    MinSnapOptions options;
    options.v_max = 2.0;
    options.periodic = periodic;
    const MinSnapTrajectory trajectory = generateMinSnap(someWaypoints(), options);
    double top = 0.0;
    for (double t = 0.0; t <= trajectory.duration(); t += 1e-4) top = std::max(top, trajectory.evaluate(t).velocity.norm());
    std::cout << "  periodic " << periodic << ": top speed on a 0.1 ms grid " << top << " m/s, duration "
              << trajectory.duration() << " s\n";
    EXPECT_LE(top, options.v_max * (1.0 + 1e-9));
    EXPECT_GT(top, options.v_max * 0.9999);  // the scaling uses the whole allowance
  }
}

TEST(MinSnap, YawWaypointsAreHitTheShortWayRound) {
  std::vector<Waypoint> waypoints = someWaypoints();
  const double yaws[] = {3.0, -3.0, -2.0, 2.5, 3.1};  // 3.0 -> -3.0 is +0.28 rad, not -6 rad
  for (std::size_t j = 0; j < waypoints.size(); ++j) {
    waypoints[j].yaw = yaws[j];
    waypoints[j].has_yaw = true;
  }
  const MinSnapTrajectory trajectory = solveMinSnap(waypoints, kDurations, false);
  double turned = 0.0;
  for (int k = 0; k < trajectory.segmentCount(); ++k) {
    const double start = trajectory.yaw.evaluateInSegment(k, 0.0, 0);
    EXPECT_NEAR(std::remainder(start - yaws[k], 2 * M_PI), 0.0, 1e-12);
    turned += std::abs(trajectory.yaw.evaluateInSegment(k, 1.0, 0) - start);
  }
  EXPECT_NEAR(turned, 0.2831853 + 1.0 + 1.7831853 + 0.6, 1e-6);
  EXPECT_NEAR(trajectory.evaluate(0.0).yaw_rate, 0.0, 1e-12);

  // Periodic: the lap ends a whole turn from where it started, rate continuous across the wrap.
  const MinSnapTrajectory lap = solveMinSnap(waypoints, kPeriodicDurations, true);
  const double end = lap.yaw.evaluate(lap.duration());
  EXPECT_NEAR(std::remainder(end - yaws[0], 2 * M_PI), 0.0, 1e-12);
  EXPECT_NEAR(lap.yaw.evaluateInSegment(lap.segmentCount() - 1, 1.0, 1), lap.yaw.evaluateInSegment(0, 0.0, 1), 1e-9);
}

TEST(MinSnap, RejectsBadWaypoints) {
  std::vector<Waypoint> one(1);
  EXPECT_THROW(solveMinSnap(one, {}, false), std::invalid_argument);
  std::vector<Waypoint> repeated = someWaypoints();
  repeated[2].position = repeated[1].position;
  EXPECT_THROW(generateMinSnap(repeated, MinSnapOptions{}), std::invalid_argument);
  std::vector<Waypoint> mixed = someWaypoints();
  mixed[3].has_yaw = true;
  EXPECT_THROW(generateMinSnap(mixed, MinSnapOptions{}), std::invalid_argument);
  std::vector<Waypoint> not_finite = someWaypoints();
  not_finite[1].position.x() = NAN;
  EXPECT_THROW(generateMinSnap(not_finite, MinSnapOptions{}), std::invalid_argument);
  EXPECT_THROW(solveMinSnap(someWaypoints(), {1.0, 1.0}, false), std::invalid_argument);
  EXPECT_THROW(solveMinSnap(someWaypoints(), {1.0, -1.0, 1.0, 1.0}, false), std::invalid_argument);
  MinSnapOptions zero_speed;
  zero_speed.v_max = 0.0;
  EXPECT_THROW(generateMinSnap(someWaypoints(), zero_speed), std::invalid_argument);
}

}  // namespace
}  // namespace sdlqr::trajectory
