// Every trajectory source goes through the one check (trajectory/path_check.hpp) when a scenario
// is loaded: a CSV file like a generated circle, the paper's ellipse; refused with the report,
// scaled (a CSV by time scaling), or flown as given on request; the entry and the exit included.
#include <gtest/gtest.h>

#include <string>

#include "sdlqr/mission/trajectory_request.hpp"
#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"
#include "agile_vehicle.hpp"
#include "test_paths.hpp"

namespace sdlqr::mission {
namespace {

constexpr double kGravity = 9.81;

PathLimits paperLimits() { return {LqrParams(), trajectory::TrajectoryGuardParams(), trajectory::TransitionParams()}; }

Trajectory circle(double speed) {
  trajectory::ClosedPathSpec spec;
  spec.speed = speed;
  spec.size = 1.5;
  spec.center = Vec3(0.0, 0.0, 1.5);
  return trajectory::sampleClosedPath(spec, kGravity);
}

TrajectoryRequest csvRequest(const Trajectory& path, const std::string& name) {
  const std::string file = sdlqr::test::tempPath(name);
  trajectory::writeTrajectoryCsv(file, path);
  TrajectoryRequest request;
  request.generator = "csv";
  request.csv_path = file;
  return request;
}

std::string refusalOf(const TrajectoryRequest& request, const PathLimits& limits = paperLimits()) {
  try {
    buildTrajectory(request, trajectory::TrajectoryParams(), limits, Vec3(1.5, 0, 1.5), 0.0, "events[3].trajectory");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "accepted";
}

// GIVEN a circle written to a CSV file WHEN it is within the vehicle THEN it is accepted as the
// generator's would be; beyond omega_max it is refused with the report and the feasible speed.
TEST(TrajectoryCheck, ACsvFileIsCheckedLikeAGeneratedPath) {
  EXPECT_EQ(refusalOf(csvRequest(circle(3.25), "circle_325.csv")), "accepted");
  const std::string refused = refusalOf(csvRequest(circle(4.0), "circle_4.csv"));
  EXPECT_NE(refused.find("events[3].trajectory: at 4 m/s the path is beyond the vehicle"), std::string::npos)
      << refused;
  EXPECT_NE(refused.find("max |omega|"), std::string::npos) << refused;
  EXPECT_NE(refused.find("feasible up to 3.5"), std::string::npos) << refused;
}

// on_infeasible: scale flies a CSV slower by time scaling: the same circle as the generator makes
// at that speed, to the flat map's exactness.
TEST(TrajectoryCheck, AScaledCsvIsTheGeneratorsPathAtTheFeasibleSpeed) {
  TrajectoryRequest request = csvRequest(circle(4.0), "circle_4_scaled.csv");
  request.on_infeasible = OnInfeasible::kScale;
  const Trajectory flown =
      buildTrajectory(request, trajectory::TrajectoryParams(), paperLimits(), Vec3(1.5, 0, 1.5), 0.0, "e");
  const double speed = velocity(flown.samples[3].x).norm();
  EXPECT_GT(speed, 3.4);
  EXPECT_LT(speed, 3.54);
  trajectory::ClosedPathSpec spec;
  spec.speed = speed;
  spec.size = 1.5;
  spec.center = Vec3(0.0, 0.0, 1.5);
  for (size_t k = 0; k < flown.samples.size(); k += 17) {
    const double t = flown.samples[k].t;
    const trajectory::FlatReference exact = trajectory::flatToReference(trajectory::closedPathAt(spec, t), kGravity);
    EXPECT_LT((flown.samples[k].x - exact.x).norm(), 1e-6) << "sample " << k;
    EXPECT_LT((flown.samples[k].u - exact.u).norm(), 2e-3) << "sample " << k;
  }
}

// The paper's ellipse asks for velocity steps its level attitude cannot fly: refused by default,
// flown as given when the scenario says on_infeasible: fly (the paper's experiment III).
TEST(TrajectoryCheck, ThePapersEllipseIsFlownOnlyWhenAskedTo) {
  TrajectoryRequest request;
  request.generator = "ellipse";
  const std::string refused = refusalOf(request);
  EXPECT_NE(refused.find("accel mismatch"), std::string::npos) << refused;
  request.on_infeasible = OnInfeasible::kFly;
  EXPECT_EQ(refusalOf(request), "accepted");
}

// The entry and the exit are part of the check: with transitions allowed 0.3 s at most, no entry
// from the hover at the circle's start reaches its speed, and the path is refused for it.
TEST(TrajectoryCheck, APathWithoutAFlyableEntryIsRefused) {
  PathLimits limits = paperLimits();
  limits.transition.max_duration = 0.3;
  const std::string refused = refusalOf(csvRequest(circle(3.0), "circle_3.csv"), limits);
  EXPECT_NE(refused.find("the way into or out of the path is beyond the vehicle"), std::string::npos) << refused;
  EXPECT_NE(refused.find("entry: none within 0.3 s"), std::string::npos) << refused;
  limits.transition.enabled = false;
  EXPECT_EQ(refusalOf(csvRequest(circle(3.0), "circle_3b.csv"), limits), "accepted") << "the old steps: unchecked";
}

// The agile vehicle (config/agile752.yaml): its limits, rotor drag modelled or not, its guard's speed.
PathLimits agileLimits(bool drag_modelled) {
  PathLimits limits = paperLimits();
  limits.lqr = test::agileLqr(drag_modelled);
  limits.guard.max_speed = 20.0;
  return limits;
}

// The agile benchmark's 3 m circle at `speed` [m/s].
TrajectoryRequest agileCircleRequest(double speed) {
  TrajectoryRequest request;
  request.generator = "circle";
  request.size = 3.0;
  request.center = Vec3(0.0, 0.0, 2.0);
  request.speed = speed;
  return request;
}

// GIVEN the agile benchmark's 3 m circle at 10.5 m/s, within c_max without the drag WHEN the scenario
// is loaded THEN with the rotor drag modelled the check refuses it on max thrust (what the controller
// flies) and names the speed feasible with it; with the drag out of the model it is accepted.
TEST(TrajectoryCheck, WithTheRotorDragModelledThePathIsJudgedOnTheThrustFlown) {
  const TrajectoryRequest request = agileCircleRequest(10.5);
  const std::string refused = refusalOf(request, agileLimits(true));
  EXPECT_NE(refused.find("max thrust"), std::string::npos) << refused;
  EXPECT_NE(refused.find("feasible up to 10.3"), std::string::npos) << refused;
  EXPECT_EQ(refusalOf(request, agileLimits(false)), "accepted");
}

// The same circle at 11.5 m/s with `on_infeasible: scale` is flown slower with the drag modelled
// (at what the check above names feasible) than without. Two tests, one a side: under the sanitizers
// each side's check of a stop from every sample takes seconds, and tests run two at a time.
double scaledCircleSpeed(bool drag_modelled) {
  TrajectoryRequest request = agileCircleRequest(11.5);
  request.on_infeasible = OnInfeasible::kScale;
  return trajectory::peakSpeed(buildTrajectory(request, trajectory::TrajectoryParams(), agileLimits(drag_modelled),
                                               Vec3(3.0, 0, 2.0), 0.0, "e"));
}

TEST(TrajectoryCheck, WithTheRotorDragModelledAScaledPathIsFlownAtTheSpeedFeasibleWithIt) {
  EXPECT_LT(scaledCircleSpeed(true), 10.35);
}

TEST(TrajectoryCheck, WithoutTheRotorDragModelledAScaledPathIsFlownFaster) { EXPECT_GT(scaledCircleSpeed(false), 11.0); }

}  // namespace
}  // namespace sdlqr::mission
