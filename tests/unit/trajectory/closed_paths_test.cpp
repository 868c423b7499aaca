// Aggressive closed paths (closed_paths.hpp), their speed fit against the vehicle's limits
// (speed_fit.hpp) and the in-flight guard's verdicts (guard.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/guard.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/validation.hpp"

namespace sdlqr::trajectory {
namespace {

constexpr double kG = 9.81;

ClosedPathSpec circle(double speed) {
  ClosedPathSpec s;
  s.shape = ClosedPathShape::kCircle;
  s.speed = speed;
  s.size = 1.0;
  return s;
}

FeasibilityLimits limits(double v_max) { return FeasibilityLimits::from(LqrParams(), v_max, 0.5); }

// Every derivative is the derivative of the one before (central differences), for both shapes.
TEST(ClosedPaths, DerivativesAreConsistentAndThePeakSpeedIsTheRequestedOne) {
  for (ClosedPathShape shape : {ClosedPathShape::kCircle, ClosedPathShape::kLemniscate}) {
    ClosedPathSpec spec = circle(2.5);
    spec.shape = shape;
    const double h = 1e-5;
    double peak = 0.0;
    for (double t = 0.0; t < closedPathPeriod(spec); t += 0.013) {
      const FlatOutput a = closedPathAt(spec, t - h), b = closedPathAt(spec, t + h), f = closedPathAt(spec, t);
      EXPECT_LT(((b.position - a.position) / (2 * h) - f.velocity).norm(), 1e-6);
      EXPECT_LT(((b.velocity - a.velocity) / (2 * h) - f.acceleration).norm(), 1e-5);
      EXPECT_LT(((b.acceleration - a.acceleration) / (2 * h) - f.jerk).norm(), 1e-4);
      EXPECT_LT(((b.jerk - a.jerk) / (2 * h) - f.snap).norm(), 1e-3);
      peak = std::max(peak, f.velocity.norm());
    }
    EXPECT_NEAR(peak, 2.5, 1e-3);
  }
}

TEST(ClosedPaths, OneClosedLapThatPassesTheBusChecks) {
  const Trajectory t = sampleClosedPath(circle(2.0), kG);
  EXPECT_TRUE(t.closed);
  EXPECT_LT((position(t.samples.back().x) - position(t.samples.front().x)).norm(), 1e-12);
  EXPECT_EQ(validateTrajectory(t, SampleChecks()), "");
  EXPECT_THROW(sampleClosedPath(circle(-1.0), kG), std::invalid_argument);
}

// A 1 m circle: 2 m/s needs ~0.8 rad/s of body rate, 3 m/s more than omega_max = 2 rad/s.
TEST(SpeedFit, FeasibleSpeedIsKeptAndAnInfeasibleOneIsCutToTheLimit) {
  const auto generate = [](double speed) { return sampleClosedPath(circle(speed), kG); };
  const SpeedFit slow = fitSpeed(generate, 2.0, limits(10.0), kG);
  EXPECT_TRUE(slow.requested.feasible());
  EXPECT_EQ(slow.feasible_speed, 2.0);

  const SpeedFit fast = fitSpeed(generate, 3.5, limits(10.0), kG);
  EXPECT_FALSE(fast.requested.feasible());
  EXPECT_FALSE(fast.requested.body_rate_ok);
  EXPECT_GT(fast.feasible_speed, 2.0);
  EXPECT_LT(fast.feasible_speed, 3.5);
  EXPECT_TRUE(checkFeasibility(fast.trajectory, limits(10.0), kG).feasible());
  EXPECT_FALSE(checkFeasibility(generate(fast.feasible_speed * 1.01), limits(10.0), kG).feasible());
  const std::string text = describeFit(fast, limits(10.0));
  EXPECT_NE(text.find("beyond the vehicle"), std::string::npos) << text;
  EXPECT_NE(text.find("max |omega|"), std::string::npos) << text;
  EXPECT_EQ(text.find('\n'), std::string::npos) << "one line";

  // The speed limit alone can make a path infeasible.
  const SpeedFit over_v = fitSpeed(generate, 2.0, limits(1.5), kG);
  EXPECT_FALSE(over_v.requested.speed_ok);
  EXPECT_NEAR(over_v.feasible_speed, 1.5, 0.01);
}

State at(const Vec3& p, const Vec3& v, const Quat& q = identityQuat()) { return makeState(p, q, v); }

// Each bound trips on its own, in the documented order, and a good tick trips nothing.
TEST(Guard, TripsOnGeofenceSpeedTiltAttitudeAndPathErrorAndNotOnAGoodTick) {
  const TrajectoryGuardParams g;
  const State ref = at(Vec3(1, 0, 1.5), Vec3(2, 0, 0));
  EXPECT_EQ(checkGuard(g, at(Vec3(1.1, 0, 1.5), Vec3(2, 0, 0)), ref), GuardTrip::kNone);
  EXPECT_EQ(checkGuard(g, at(Vec3(2.5, 0, 1.5), Vec3(2, 0, 0)), ref), GuardTrip::kPathError);
  EXPECT_EQ(checkGuard(g, at(Vec3(1.1, 0, 1.5), Vec3(7, 0, 0)), ref), GuardTrip::kSpeed);
  EXPECT_EQ(checkGuard(g, at(Vec3(11, 0, 1.5), Vec3::Zero()), at(Vec3(11, 0, 1.5), Vec3::Zero())), GuardTrip::kGeofence);
  EXPECT_EQ(checkGuard(g, at(Vec3(0, 0, -1.5), Vec3::Zero()), at(Vec3(0, 0, -1.5), Vec3::Zero())), GuardTrip::kGeofence);
  // Rolled 75 degrees where the reference is rolled 60: within the attitude bound, beyond the tilt.
  const auto roll = [](double deg) { return Quat(std::cos(deg * M_PI / 360.0), std::sin(deg * M_PI / 360.0), 0, 0); };
  EXPECT_EQ(checkGuard(g, at(Vec3(1, 0, 1.5), Vec3(2, 0, 0), roll(75)), at(Vec3(1, 0, 1.5), Vec3(2, 0, 0), roll(60))),
            GuardTrip::kTilt);
  // Rolled 30 degrees one way where the reference is rolled 30 the other: 60 degrees apart.
  EXPECT_EQ(checkGuard(g, at(Vec3(1, 0, 1.5), Vec3(2, 0, 0), roll(30)), at(Vec3(1, 0, 1.5), Vec3(2, 0, 0), roll(-30))),
            GuardTrip::kAttitudeError);
  EXPECT_NEAR(attitudeError(roll(30), Quat(-roll(-30))), 60.0 * M_PI / 180.0, 1e-12) << "either sign of q";
}

}  // namespace
}  // namespace sdlqr::trajectory
