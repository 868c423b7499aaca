#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "sdlqr/math/model.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/feasibility.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/validation.hpp"

namespace sdlqr::trajectory {
namespace {

TEST(PaperEllipse, ThirtySixSamplesPerLapAtTwoMetresPerSecondLevelHover) {
  const TrajectoryParams params;
  const Trajectory ellipse = paperEllipse(params, kDefaultGravity);
  ASSERT_EQ(ellipse.samples.size(), 37u);  // 36 per lap and the closing sample
  EXPECT_TRUE(ellipse.closed);
  EXPECT_EQ(validateTrajectory(ellipse, params.sampleChecks()), "");
  EXPECT_LT((ellipse.samples.back().x - ellipse.samples.front().x).norm(), 1e-15);
  for (int k = 0; k < 36; ++k) {
    const TrajectorySample& s = ellipse.samples[k];
    const TrajectorySample& next = ellipse.samples[k + 1];
    const double a = 2.0 * M_PI * k / 36.0;
    EXPECT_LT((position(s.x) - Vec3(1.5 * std::sin(a), -1.2 * std::cos(a), 0.5 * std::sin(a) + 1.0)).norm(), 1e-15);
    EXPECT_NEAR(velocity(s.x).norm(), 2.0, 1e-14);
    const Vec3 to_next = position(next.x) - position(s.x);
    EXPECT_NEAR(velocity(s.x).normalized().dot(to_next.normalized()), 1.0, 1e-14);
    EXPECT_NEAR(next.t - s.t, to_next.norm() / 2.0, 1e-14);
    EXPECT_LT((orientation(s.x) - identityQuat()).norm(), 1e-15);
    EXPECT_EQ(s.u[kThrust], kDefaultGravity);
    EXPECT_EQ(bodyRate(s.u).norm(), 0.0);
  }
  std::cout << "  ellipse lap " << ellipse.samples.back().t << " s\n";
}

TEST(PaperEllipse, IsReportedInconsistent) {
  const Trajectory ellipse = paperEllipse(TrajectoryParams{}, kDefaultGravity);
  const FeasibilityReport report =
      checkFeasibility(ellipse, FeasibilityLimits::from(LqrParams{}, 2.0, 0.5), kDefaultGravity);
  std::cout << "  ellipse: largest mismatch between demanded and produced acceleration " << report.max_accel_mismatch
            << " m/s^2\n";
  EXPECT_TRUE(report.speed_ok && report.max_thrust_ok && report.min_thrust_ok && report.body_rate_ok);
  EXPECT_FALSE(report.consistency_ok);  // the paper's point: velocity turns, inputs say hover
  // v^2 / r bounds the demanded centripetal acceleration: 4 / 1.5 .. 4 / 0.5 (tightest radius).
  EXPECT_GT(report.max_accel_mismatch, 4.0 / 1.6);
}

TEST(PaperEllipse, YawParameterTurnsTheLevelAttitude) {
  TrajectoryParams params;
  params.yaw = 0.8;
  for (const TrajectorySample& s : paperEllipse(params, kDefaultGravity).samples) {
    EXPECT_NEAR(quat::yaw(orientation(s.x)), 0.8, 1e-15);
    EXPECT_NEAR(quat::tilt(orientation(s.x)), 0.0, 1e-7);
  }
}

void checkPaperMinSnap(const MinSnapTrajectory& polynomial, double v_max, const char* name) {
  const TrajectoryParams params;
  const FeasibilityLimits limits = FeasibilityLimits::from(LqrParams{}, v_max, params.accel_mismatch_max);
  const FeasibilityReport report = checkFeasibility(polynomial, limits, kDefaultGravity, params.check_dt);
  std::cout << "  " << name << ": " << polynomial.duration() << " s, " << polynomial.segmentCount()
            << " segments, speed " << report.max_speed << " m/s, c in [" << report.min_thrust << ", "
            << report.max_thrust << "] m/s^2, max |omega| " << report.max_body_rate << " rad/s\n";
  EXPECT_TRUE(report.feasible()) << formatReport(report, limits);
  EXPECT_NEAR(report.max_speed, v_max, 1e-6 * v_max);

  // Through every waypoint, starting and ending hovering on p0.
  const std::vector<Waypoint> path = paperPathWaypoints(params);
  ASSERT_EQ(static_cast<int>(path.size()), polynomial.segmentCount() + 1);
  for (int j = 0; j < polynomial.segmentCount(); ++j) {
    EXPECT_LT((polynomial.evaluate(polynomial.axes[0].segmentStart(j)).position - path[j].position).norm(), 1e-12);
  }
  const Trajectory sampled = sampleTrajectory(polynomial, params.sample_dt, kDefaultGravity);
  EXPECT_EQ(validateTrajectory(sampled, params.sampleChecks()), "");
  EXPECT_LT((position(sampled.samples.back().x) - Vec3(0.0, -1.2, 1.0)).norm(), 1e-12);
  EXPECT_LT(velocity(sampled.samples.back().x).norm(), 1e-12);
  EXPECT_NEAR(sampled.samples.back().u[kThrust], kDefaultGravity, 1e-9);
  EXPECT_NEAR(sampled.samples[1].t - sampled.samples[0].t, 0.1, 1e-15);
  const FeasibilityReport sampled_report = checkFeasibility(sampled, limits, kDefaultGravity);
  std::cout << "    sampled at 0.1 s: acceleration mismatch " << sampled_report.max_accel_mismatch << " m/s^2\n";
  EXPECT_TRUE(sampled_report.consistency_ok);
}

TEST(PaperMinSnap, FastCaseIsFeasibleAtThreeMetresPerSecond) {
  checkPaperMinSnap(paperMinSnapFast(TrajectoryParams{}), 3.0, "minsnap fast");
}

TEST(PaperMinSnap, SlowCaseIsFeasibleAtOneMetrePerSecond) {
  checkPaperMinSnap(paperMinSnapSlow(TrajectoryParams{}), 1.0, "minsnap slow");
}

TEST(PaperMinSnap, PeriodicVariantIsOneClosedLap) {
  TrajectoryParams params;
  params.periodic = true;
  const MinSnapTrajectory lap = paperMinSnapFast(params);
  EXPECT_EQ(lap.segmentCount(), 4);
  const Trajectory sampled = sampleTrajectory(lap, params.sample_dt, kDefaultGravity);
  EXPECT_TRUE(sampled.closed);
  EXPECT_EQ(validateTrajectory(sampled, params.sampleChecks()), "");
  EXPECT_LT((sampled.samples.back().x - sampled.samples.front().x).norm(), 1e-9);
  EXPECT_LT((sampled.samples.back().u - sampled.samples.front().u).norm(), 1e-9);
  const FeasibilityReport report =
      checkFeasibility(lap, FeasibilityLimits::from(LqrParams{}, 3.0, 0.5), kDefaultGravity, params.check_dt);
  std::cout << "  periodic lap: " << lap.duration() << " s, c in [" << report.min_thrust << ", " << report.max_thrust
            << "], max |omega| " << report.max_body_rate << "\n";
  EXPECT_TRUE(report.feasible());
}

TEST(Feasibility, ViolatedLimitsAreReported) {
  LqrParams tight;
  tight.omega_max = 0.5;
  tight.c_max = 10.0;
  const FeasibilityLimits limits = FeasibilityLimits::from(tight, 2.5, 0.5);
  const FeasibilityReport report = checkFeasibility(paperMinSnapFast(TrajectoryParams{}), limits, kDefaultGravity, 1e-3);
  EXPECT_FALSE(report.speed_ok);
  EXPECT_FALSE(report.max_thrust_ok);
  EXPECT_TRUE(report.min_thrust_ok);
  EXPECT_FALSE(report.body_rate_ok);
  EXPECT_FALSE(report.feasible());
  const std::string text = formatReport(report, limits);
  EXPECT_NE(text.find("NOT feasible"), std::string::npos);
  EXPECT_NE(text.find("FAIL"), std::string::npos);
}

}  // namespace
}  // namespace sdlqr::trajectory
