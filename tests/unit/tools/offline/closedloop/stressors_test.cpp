// The stressors of config/scenarios/ flown in-process (the cores the bus runs): plant mismatch,
// wind with gusts, airborne starts up to upside down, a throw — each measured, and each check shown
// failing on a flight that went wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/closedloop/closed_loop.hpp"
#include "sdlqr/trajectory/closed_paths.hpp"
#include "test_paths.hpp"
#include "closedloop_test_flights.hpp"
#include "closedloop_test_scenarios.hpp"

namespace sdlqr {
namespace {

using ::sdlqr::test::scenarioNamed;

using ::sdlqr::test::kSourceDir;

struct StressedFlight : test::AnalyzedFlight {
  int64_t throws_detected = 0;
};

StressedFlight fly(const mission::Scenario& scenario) {
  const closedloop::StackConfig config = closedloop::StackConfig::load(scenario.vehicle_path);
  closedloop::ClosedLoop loop(config, scenario);
  loop.run();
  StressedFlight f;
  f.log = loop.log();
  f.report = analysis::analyzeFlight(f.log, scenario);
  const Counters& counters = loop.mission().health().counters();
  f.throws_detected = counters.value(counters.find("throw.detected"));
  return f;
}

const analysis::Check* checkNamed(const analysis::FlightReport& r, const std::string& key) {
  for (const analysis::Check& c : r.checks) {
    if (c.key == key) return &c;
  }
  return nullptr;
}

void printRecovery(const StressedFlight& f) {
  ASSERT_TRUE(f.report.recovery.has_value());
  const analysis::RecoveryReport& r = *f.report.recovery;
  std::cout << f.report.scenario << ": initial tilt " << r.initial_tilt_deg << " deg, level after " << r.level_time
            << " s, height lost " << r.height_lost << " m, settled after " << r.settle_time << " s"
            << (r.throw_start ? ", detected " + std::to_string(r.detect_delay) + " s after release" : "")
            << (f.report.crashed ? ", CRASHED" : "") << "\n";
}

// GIVEN the same hover flown on the vehicle file's mass and on a plant 20 % heavier THEN the
// heavier one hangs measurably lower in the same hold (the controller assumes the file's mass).
TEST(Stressors, MassMismatchChangesTheHoverMeasurably) {
  const mission::Scenario heavy = scenarioNamed("mass_plus20");
  mission::Scenario nominal = heavy;
  nominal.sim.plant = sim::PlantOverride();
  const StressedFlight a = fly(nominal);
  const StressedFlight b = fly(heavy);
  const double nominal_error = test::meanHeightError(a.log, 6.0, 9.0);
  const double heavy_error = test::meanHeightError(b.log, 6.0, 9.0);
  std::cout << "hover z error, 6-9 s: nominal mass " << nominal_error << " m, +20 % mass " << heavy_error << " m\n";
  EXPECT_LT(heavy_error, nominal_error - 0.02);
  test::expectEveryCheckPasses(b.report, b.report.scenario);
}

// The gusts are drawn from the scenario's seed: the same seed flies the same flight bit for bit,
// another seed other gusts.
TEST(Stressors, WindAndGustsRepeatForASeed) {
  const mission::Scenario windy = scenarioNamed("wind_gusts");
  const StressedFlight a = fly(windy);
  const StressedFlight b = fly(windy);
  mission::Scenario other_seed = windy;
  other_seed.seed += 1;
  const StressedFlight c = fly(other_seed);
  ASSERT_EQ(a.log.sim_truth.size(), b.log.sim_truth.size());
  for (size_t i = 0; i < a.log.sim_truth.size(); ++i) {
    ASSERT_EQ(a.log.sim_truth[i].position, b.log.sim_truth[i].position) << "sample " << i;
  }
  ASSERT_EQ(a.log.sim_truth.size(), c.log.sim_truth.size());
  double largest_difference = 0.0;
  for (size_t i = 0; i < a.log.sim_truth.size(); ++i) {
    largest_difference =
        std::max(largest_difference, (a.log.sim_truth[i].position - c.log.sim_truth[i].position).norm());
  }
  EXPECT_GT(largest_difference, 0.02);
  // The steady wind pushes downwind: the hold sits measurably downwind of no wind.
  mission::Scenario calm = windy;
  calm.sim.wind = sim::WindParams();
  const StressedFlight d = fly(calm);
  const double windy_error = test::meanHorizontalError(a.log, 6.0, 12.0);
  const double calm_error = test::meanHorizontalError(d.log, 6.0, 12.0);
  std::cout << "wind_gusts: mean horizontal hold error 6-12 s " << windy_error << " m (calm " << calm_error
            << " m), seeds differ by up to " << largest_difference << " m\n";
  EXPECT_GT(windy_error, calm_error + 0.05);
  test::expectEveryCheckPasses(a.report, a.report.scenario);
}

// 60, 120 and 180 degrees (upside down): every recovery criterion of the scenario passes (level
// for good within 3 s, at least 1 m above the ground, settled in the final hold within 8 s).
TEST(Stressors, AirborneStartsUpToUpsideDownRecover) {
  for (const char* name : {"recover_60", "recover_120", "recover_180"}) {
    const StressedFlight f = fly(scenarioNamed(name));
    printRecovery(f);
    EXPECT_FALSE(f.report.crashed) << name;
    test::expectEveryCheckPasses(f.report, f.report.scenario);
  }
}

// Negative: the rejoin chasing the place it first saw the vehicle (the recovery ends at once: any
// tilt and speed count as righted) flies back tilted and fails the 120-degree start's level check.
TEST(Stressors, ChasingTheFirstSeenPlaceFailsTheLevelCheckAt120Degrees) {
  mission::Scenario scenario = scenarioNamed("recover_120");
  closedloop::StackConfig config = closedloop::StackConfig::load(scenario.vehicle_path);
  config.controller.recovery_tilt_deg = 90.0;
  config.controller.recovery_speed = 1e6;
  closedloop::ClosedLoop loop(config, scenario);
  loop.run();
  const analysis::FlightReport report = analysis::analyzeFlight(loop.log(), scenario);
  const analysis::Check* level = checkNamed(report, "recovery_level_time");
  ASSERT_NE(level, nullptr);
  EXPECT_FALSE(level->pass) << "level after " << level->value << " s";
}

// Negative: the same airborne start never armed falls to the ground; every recovery check fails.
TEST(Stressors, AnAirborneStartNeverArmedFailsTheRecoveryChecks) {
  mission::Scenario unarmed = scenarioNamed("recover_60");
  unarmed.events.clear();
  const StressedFlight f = fly(unarmed);
  for (const char* key : {"recovery_level_time", "recovery_settle_time", "recovery_height_lost"}) {
    const analysis::Check* c = checkNamed(f.report, key);
    ASSERT_NE(c, nullptr) << key;
    EXPECT_FALSE(c->pass) << key << " = " << c->value;
  }
}

TEST(Stressors, ThrowIsDetectedArmedAndRecovered) {
  const StressedFlight f = fly(scenarioNamed("throw"));
  printRecovery(f);
  EXPECT_EQ(f.throws_detected, 1);
  test::expectEveryCheckPasses(f.report, f.report.scenario);
}

// Negative: thrown without throw mode, nothing arms the motors: the throw checks fail.
TEST(Stressors, AThrowWithoutThrowModeFailsTheThrowChecks) {
  mission::Scenario no_mode = scenarioNamed("throw");
  no_mode.throw_mode = mission::ThrowModeParams();
  const StressedFlight f = fly(no_mode);
  EXPECT_EQ(f.throws_detected, 0);
  for (const char* key : {"throw_detect_delay", "recovery_level_time", "recovery_settle_time"}) {
    const analysis::Check* c = checkNamed(f.report, key);
    ASSERT_NE(c, nullptr) << key;
    EXPECT_FALSE(c->pass) << key << " = " << c->value;
  }
}

// Negative: throw mode armed through a whole normal flight (take-off, 1 m jumps up and down, a
// pull, the landing) never sees a throw.
TEST(Stressors, NoThrowIsDetectedInANormalFlight) {
  mission::Scenario flight = scenarioNamed("hover_jumps");
  flight.throw_mode.at = 0.0;
  const StressedFlight f = fly(flight);
  EXPECT_EQ(f.throws_detected, 0);
  EXPECT_GT(f.report.setpoints.size(), 6u);  // the flight flew
}

// A fast closed path the vehicle can fly is tracked to the end of its time, never aborted; the
// lemniscate asked beyond the vehicle flies time-scaled.
TEST(Stressors, FeasibleFastPathsAreFlownAndNotAborted) {
  const StressedFlight f = fly(scenarioNamed("aggressive_path"));
  ASSERT_EQ(f.report.trajectories.size(), 2u);
  for (const analysis::PathTrackingReport& t : f.report.trajectories) {
    std::cout << t.label << ": path error RMS " << t.path_error_rms << " m, max " << t.path_error_max << " m, "
              << t.laps << " laps\n";
    EXPECT_GT(t.laps, 1.0);
  }
  EXPECT_EQ(f.report.trajectory_aborts, 0);
  test::expectEveryCheckPasses(f.report, f.report.scenario);
}

// A reference the vehicle cannot follow (a foreign TRAJECTORY whose samples claim rest and hover
// thrust, within every limit the controller checks, but whose positions run off at 12 m/s towards
// the geofence) is aborted by the guard into a hold where the vehicle is: counted in the
// controller's HEARTBEAT counters, seen by the analysis, and the vehicle stops well inside the fence.
// The same path whose samples say 12 m/s is refused on arrival (beyond the guard's speed).
TEST(Stressors, GuardAbortsARunawayTrajectoryIntoAHold) {
  mission::Scenario hover = scenarioNamed("hover_steady");
  hover.duration = 16.0;
  const closedloop::StackConfig config = closedloop::StackConfig::load(hover.vehicle_path);
  closedloop::ClosedLoop loop(config, hover);
  while (loop.utime() < 8'000'000) loop.step();
  const SimTruth before = loop.log().sim_truth.messages.back();
  Trajectory runaway;
  runaway.utime = loop.utime();
  runaway.seq = 0;
  runaway.tracking = ReferenceMode::kTemporal;
  for (int k = 0; k <= 60; ++k) {
    TrajectorySample s;
    s.t = 0.05 * k;
    s.x = makeState(before.position + Vec3(12.0 * s.t, 0, 0), identityQuat(), Vec3(12.0, 0, 0));
    s.u = makeInput(Vec3::Zero(), kDefaultGravity);
    runaway.samples.push_back(s);
  }
  loop.inject(runaway);
  EXPECT_EQ(loop.controller().health().rejections(Stream::kTrajectory, RejectReason::kRefused), 1) << "12 m/s declared: beyond the guard's 6";
  for (TrajectorySample& s : runaway.samples) velocity(s.x).setZero();
  runaway.seq = 1;
  loop.inject(runaway);
  loop.run();
  const Counters& counters = loop.controller().health().counters();
  EXPECT_EQ(counters.value(counters.find("trajectory.guard_abort")), 1);
  const analysis::FlightReport report = analysis::analyzeFlight(loop.log(), hover);
  EXPECT_EQ(report.trajectory_aborts, 1);
  double farthest = 0.0;
  for (const SimTruth& s : loop.log().sim_truth.messages) {
    farthest = std::max(farthest, (s.position - before.position).norm());
  }
  const SimTruth after = loop.log().sim_truth.messages.back();
  std::cout << "runaway: farthest " << farthest << " m from the hold, ends " << (after.position - before.position).norm()
            << " m from it\n";
  EXPECT_LT(farthest, 2.0);
  EXPECT_FALSE(report.crashed);
}

// A foreign TRAJECTORY beyond the vehicle (a 1.5 m circle at 4 m/s, ||omega|| above 2 rad/s) sent
// to the hovering stack: refused on arrival by default; with controller.trajectory_beyond_limits:
// scale, flown time-scaled — counted, said in the controller's last error, no guard abort, no crash.
struct UploadOutcome {
  int64_t refused = 0, scaled = 0, guard_aborts = 0;
  std::string last_error;
  bool crashed = true;
};

UploadOutcome uploadFastCircle(controller::UploadBeyondLimits policy) {
  mission::Scenario hover = scenarioNamed("hover_steady");
  hover.duration = 20.0;
  closedloop::StackConfig config = closedloop::StackConfig::load(hover.vehicle_path);
  config.controller.trajectory_beyond_limits = policy;
  closedloop::ClosedLoop loop(config, hover);
  while (loop.utime() < 8'000'000) loop.step();
  trajectory::ClosedPathSpec circle;
  circle.center = loop.log().sim_truth.messages.back().position - Vec3(1.5, 0, 0);  // the vehicle on the circle
  circle.size = 1.5;
  circle.speed = 4.0;
  Trajectory upload = trajectory::sampleClosedPath(circle, kDefaultGravity);
  upload.utime = loop.utime();
  upload.seq = 0;
  upload.tracking = ReferenceMode::kTemporal;
  loop.inject(upload);
  loop.run();
  const ProcessHealth& health = loop.controller().health();
  UploadOutcome out;
  out.refused = health.rejections(Stream::kTrajectory, RejectReason::kRefused);
  out.scaled = health.counters().value(health.counters().find("trajectory.scaled"));
  out.guard_aborts = health.counters().value(health.counters().find("trajectory.guard_abort"));
  out.last_error = health.lastError();
  out.crashed = analysis::analyzeFlight(loop.log(), hover).crashed;
  return out;
}

TEST(Stressors, AnUploadBeyondTheVehicleIsFlownTimeScaledWhereTheVehicleFileSaysScale) {
  const UploadOutcome scaled = uploadFastCircle(controller::UploadBeyondLimits::kScale);
  std::cout << "scaled: " << scaled.last_error << "\n";
  EXPECT_EQ(scaled.refused, 0);
  EXPECT_EQ(scaled.scaled, 1);
  EXPECT_NE(scaled.last_error.find("flown time-scaled: at 4 m/s the path is beyond the vehicle"), std::string::npos);
  EXPECT_EQ(scaled.guard_aborts, 0);
  EXPECT_FALSE(scaled.crashed);
  // Negative: the default refuses it with the report, and nothing is scaled.
  const UploadOutcome refused = uploadFastCircle(controller::UploadBeyondLimits::kRefuse);
  EXPECT_EQ(refused.refused, 1);
  EXPECT_EQ(refused.scaled, 0);
  EXPECT_NE(refused.last_error.find("refused: beyond the vehicle"), std::string::npos) << refused.last_error;
}

// A forged SIM_CLOCK that leaps ahead (a fuzzer's huge utime, as faults_fuzz_flight once sent) mid-hover:
// the mission refuses it (ClockGate) and keeps its clock; its events still play on the real one.
TEST(Stressors, TheMissionRefusesAClockThatLeapsAhead) {
  const mission::Scenario hover = scenarioNamed("hover_steady");  // lands at 36 s of 40
  const closedloop::StackConfig config = closedloop::StackConfig::load(hover.vehicle_path);
  closedloop::ClosedLoop loop(config, hover);
  while (loop.utime() < 5'000'000) loop.step();
  SimClockTick forged;
  forged.utime = 27'094'305'290'949'000;  // the one seen: 2.7e10 s
  loop.inject(forged);
  const ProcessHealth& health = loop.mission().health();
  EXPECT_EQ(health.rejections(Stream::kSimClock, RejectReason::kTimeFuture), 1);
  EXPECT_LT(loop.mission().now(), 6'000'000) << "the mission's clock leapt";
  loop.run();
  EXPECT_EQ(loop.mission().now() / 1'000'000, static_cast<int64_t>(hover.duration)) << "to its end on the real clock";
  const analysis::FlightReport report = analysis::analyzeFlight(loop.log(), hover);
  test::expectEveryCheckPasses(report, report.scenario);
}

// An infeasible path is refused when the scenario is loaded, with the report in one line naming
// the event; the same path with on_infeasible: scale loads.
TEST(Stressors, InfeasiblePathIsRefusedWithTheFeasibilityReport) {
  mission::Scenario s = scenarioNamed("aggressive_path");
  mission::ScenarioEvent* lemniscate = nullptr;
  for (mission::ScenarioEvent& e : s.events) {
    if (e.kind == mission::ScenarioEvent::Kind::kTrajectory && e.trajectory.generator == "lemniscate") lemniscate = &e;
  }
  ASSERT_NE(lemniscate, nullptr);
  const closedloop::StackConfig config = closedloop::StackConfig::load(s.vehicle_path);
  lemniscate->trajectory.on_infeasible = mission::OnInfeasible::kRefuse;
  try {
    closedloop::ClosedLoop loop(config, s);
    ADD_FAILURE() << "an infeasible lemniscate was accepted";
  } catch (const ConfigError& e) {
    const std::string what = e.what();
    std::cout << what << "\n";
    EXPECT_NE(what.find("events[5].trajectory"), std::string::npos) << what;
    EXPECT_NE(what.find("beyond the vehicle"), std::string::npos) << what;
    EXPECT_NE(what.find("feasible up to"), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace sdlqr
