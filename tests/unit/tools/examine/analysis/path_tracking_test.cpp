// Trajectory metrics on synthetic flights whose answers are known by construction: closest-point
// error, time-indexed error, completion, laps, skipped samples, saturation, thrust, pull return.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <tuple>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/analysis/path_tracking.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "analysis_test_time.hpp"

namespace sdlqr {
namespace {

using ::sdlqr::test::micros;

// Samples every dt along `at(t)` for t in [0, duration], moving at unit speed.
template <class PathAt>
Trajectory makeTrajectory(PathAt at, double duration, double dt, ReferenceMode tracking, bool closed = false) {
  Trajectory out;
  out.seq = 3;
  out.utime = micros(10.0);
  out.start_utime = micros(10.0);
  out.tracking = tracking;
  out.closed = closed;
  const int n = static_cast<int>(std::llround(duration / dt));
  for (int k = 0; k <= n; ++k) {
    TrajectorySample s;
    s.t = k * dt;
    s.x = makeState(at(s.t), identityQuat(), Vec3::Zero());
    s.u = makeInput(Vec3::Zero(), 9.81);
    out.samples.push_back(s);
  }
  return out;
}

// L-shaped path: 2 m along +x, then 2 m along +y, at 1 m/s, z = 1.
Vec3 lPath(double t) { return t <= 2.0 ? Vec3(t, 0.0, 1.0) : Vec3(2.0, t - 2.0, 1.0); }

void addTruth(logger::FlightLog& log, double t, const Vec3& p) {
  SimTruth s;
  s.utime = micros(t);
  s.position = p;
  s.on_ground = false;
  log.sim_truth.messages.push_back(s);
  log.sim_truth.receive_utime.push_back(s.utime);
}

void addReference(logger::FlightLog& log, double t, int index, double gamma, ReferenceMode mode, int64_t seq = 3) {
  Reference r;
  r.utime = micros(t);
  r.index = index;
  r.gamma = gamma;
  r.mode = mode;
  r.trajectory_seq = seq;
  log.reference.messages.push_back(r);
  log.reference.receive_utime.push_back(r.utime);
}

// `demand`: what the control law asked for before its clip (NaN: the same as `thrust`).
void addCommand(logger::FlightLog& log, double t, double thrust, int8_t saturated, double demand = std::nan("")) {
  RateCommand c;
  c.utime = micros(t);
  c.thrust = thrust;
  c.thrust_demand = std::isnan(demand) ? thrust : demand;
  c.saturated = saturated;
  log.rate_command.messages.push_back(c);
  log.rate_command.receive_utime.push_back(c.utime);
}

void addTrajectory(logger::FlightLog& log, const Trajectory& trajectory) {
  log.trajectory.messages.push_back(trajectory);
  log.trajectory.receive_utime.push_back(trajectory.utime);
}

// The reference on segment (i-1, i) of a 0.1 s sampled trajectory at trajectory time tau.
void referenceAt(logger::FlightLog& log, double t, double tau, int samples, ReferenceMode mode, int64_t seq = 3) {
  const double k = std::min(tau / 0.1, static_cast<double>(samples - 1));
  int index = std::max(1, static_cast<int>(std::ceil(k - 1e-9)));
  index = std::min(index, samples - 1);
  addReference(log, t, index, std::clamp(k - (index - 1), 0.0, 1.0), mode, seq);
}

TEST(PathGeometry, ClosestPointOnThePolyline) {
  const Trajectory trajectory = makeTrajectory(lPath, 4.0, 0.1, ReferenceMode::kSpatial);
  const analysis::PathGeometry path(trajectory);
  EXPECT_NEAR(path.length(), 4.0, 1e-12);
  const auto inside = path.closest(Vec3(1.0, 0.3, 1.0));
  EXPECT_NEAR(inside.distance, 0.3, 1e-12);
  EXPECT_NEAR(inside.arc, 1.0, 1e-12);
  // Outside the corner: the corner itself is the closest point.
  const auto corner = path.closest(Vec3(2.3, -0.4, 1.0));
  EXPECT_NEAR(corner.distance, 0.5, 1e-12);
  EXPECT_NEAR(corner.arc, 2.0, 1e-12);
  const auto second_leg = path.closest(Vec3(1.8, 1.5, 1.2));
  EXPECT_NEAR(second_leg.distance, std::hypot(0.2, 0.2), 1e-12);
  EXPECT_NEAR(second_leg.arc, 3.5, 1e-12);
  EXPECT_NEAR(path.arcAt(25, 0.5), 2.45, 1e-12);
}

TEST(PathTracking, ConstantOffsetGivesItsRmsPerAxisAndCompletion) {
  logger::FlightLog log;
  const Trajectory trajectory = makeTrajectory(lPath, 4.0, 0.1, ReferenceMode::kSpatial);
  addTrajectory(log, trajectory);
  const Vec3 offset(0.0, 0.0, 0.04);  // straight above the path: the closest point is below
  const double lag = 0.25;            // [s] behind schedule
  for (int i = 0; i <= 500; ++i) {
    const double tau = i * 0.01;
    const double along = std::clamp(tau - lag, 0.0, 4.0);
    addTruth(log, 10.0 + tau, lPath(along) + offset);
    if (i % 2 == 0) referenceAt(log, 10.0 + tau, along, 41, ReferenceMode::kSpatial);
  }
  const auto reports = analysis::analyzePathTracking(log);
  ASSERT_EQ(reports.size(), 1u);
  const analysis::PathTrackingReport& r = reports[0];
  EXPECT_NEAR(r.path_error_rms, 0.04, 1e-9);
  EXPECT_NEAR(r.path_error_max, 0.04, 1e-9);
  EXPECT_NEAR(r.path_error_rms_axis[0], 0.0, 1e-9);
  EXPECT_NEAR(r.path_error_rms_axis[2], 0.04, 1e-9);
  // Behind schedule by 0.25 s at 1 m/s (more around the corner, where the chord is shorter).
  EXPECT_NEAR(r.time_error_max, std::hypot(lag, 0.04), 1e-6);
  EXPECT_TRUE(r.completed);
  EXPECT_NEAR(r.completion_time, 4.0 - 0.05 + lag, 0.021);  // completion_radius before the end
  EXPECT_NEAR(r.laps, 1.0, 1e-9);
  EXPECT_EQ(r.samples_passed, 40);
  EXPECT_TRUE(r.skipped.empty());
  // The window ends 5 cm before the end (completion_radius): the last sample is 5 cm ahead.
  EXPECT_NEAR(r.worst_visit, std::hypot(0.05, 0.04), 1e-9);
}

// The paper's disturbance experiment reduced to its geometry: held 0.5 m outside the corner of
// an L for 2 s. Temporal: the reference runs around the corner meanwhile and the vehicle cuts
// across to it. Spatial: the reference waits, the vehicle returns to the corner and follows.
struct HeldAtCorner {
  logger::FlightLog log;
  analysis::PathTrackingReport report;
};

HeldAtCorner flyHeldAtCorner(ReferenceMode mode) {
  HeldAtCorner out;
  const Trajectory trajectory = makeTrajectory(lPath, 4.0, 0.1, mode);
  addTrajectory(out.log, trajectory);
  const Vec3 held(1.6, -0.5, 1.0);  // pulled off at x = 1.6
  for (int i = 0; i <= 800; ++i) {
    const double tau = i * 0.01;
    Vec3 p;
    double ref_tau;
    if (tau < 1.6) {  // on the path
      p = lPath(tau);
      ref_tau = tau;
    } else if (tau < 3.6) {  // held
      p = held;
      ref_tau = mode == ReferenceMode::kTemporal ? tau : 1.6;
    } else if (mode == ReferenceMode::kTemporal) {  // straight for the (moving) reference
      const double f = std::min(1.0, (tau - 3.6) / 1.0);
      p = held + f * (lPath(std::min(4.0, 4.6)) - held);
      ref_tau = tau;
    } else {  // back to the path within 0.5 s, then along it
      const double f = std::min(1.0, (tau - 3.6) / 0.5);
      p = held + f * (lPath(1.6) - held);
      ref_tau = 1.6;
      if (tau >= 4.1) p = lPath(std::min(4.0, 1.6 + (tau - 4.1))), ref_tau = std::min(4.0, 1.6 + (tau - 4.1));
    }
    addTruth(out.log, 10.0 + tau, p);
    if (i % 2 == 0) referenceAt(out.log, 10.0 + tau, ref_tau, 41, mode);
  }
  Disturbance pull;
  pull.utime = pull.start_utime = micros(11.6);
  pull.duration = 2.0;
  out.log.disturbance.messages.push_back(pull);
  out.log.disturbance.receive_utime.push_back(pull.utime);
  analysis::PathTrackingOptions options;
  options.skip_radius = 0.25;
  const auto reports = analysis::analyzePathTracking(out.log, options);
  EXPECT_EQ(reports.size(), 1u);
  if (!reports.empty()) out.report = reports[0];
  return out;
}

TEST(PathTracking, TemporalReferenceRunningAheadSkipsTheCorner) {
  const HeldAtCorner temporal = flyHeldAtCorner(ReferenceMode::kTemporal);
  const HeldAtCorner spatial = flyHeldAtCorner(ReferenceMode::kSpatial);
  std::cout << "held at the corner: temporal skipped " << temporal.report.skipped.size() << " of "
            << temporal.report.samples_passed << ", spatial " << spatial.report.skipped.size() << " of "
            << spatial.report.samples_passed << " (worst visit " << spatial.report.worst_visit << " m)\n";
  EXPECT_EQ(spatial.report.samples_passed, 40);
  EXPECT_TRUE(spatial.report.skipped.empty());
  ASSERT_FALSE(temporal.report.skipped.empty());
  // The chord from (1.6, -0.5) to (2, 2) passes 0.32 m from the corner (2, 0) and 0.16 (2 - y) m
  // from (2, y): the corner and the first samples of the second leg are skipped.
  for (const auto& s : temporal.report.skipped) EXPECT_GT(s.closest, 0.25);
  EXPECT_GE(temporal.report.skipped.size(), 3u);
  // Samples before the pull were visited in both.
  EXPECT_GT(temporal.report.skipped.front().arc, 1.6);
}

TEST(PathTracking, PullReturnTimeAndDistanceAtRelease) {
  const HeldAtCorner spatial = flyHeldAtCorner(ReferenceMode::kSpatial);
  ASSERT_EQ(spatial.report.pulls.size(), 1u);
  const analysis::PathPull& pull = spatial.report.pulls[0];
  EXPECT_NEAR(pull.release, 13.6, 1e-9);
  EXPECT_NEAR(pull.distance_at_release, 0.5, 1e-9);
  // Straight back to (1.6, 0) in 0.5 s: below 0.1 m once 80 % of the way.
  EXPECT_NEAR(pull.return_time, 0.4, 0.011);
  EXPECT_NEAR(pull.max_distance, 0.5, 1e-9);
}

TEST(PathTracking, ClosedTrajectoryCountsLapsAndItsSamplesPerLap) {
  logger::FlightLog log;
  const double radius = 1.0, speed = 1.0;
  const double period = 2.0 * M_PI * radius / speed;
  const int per_lap = 36;
  Trajectory trajectory;
  trajectory.seq = 3;
  trajectory.utime = trajectory.start_utime = micros(10.0);
  trajectory.closed = true;
  for (int k = 0; k <= per_lap; ++k) {
    const double a = 2.0 * M_PI * (k % per_lap) / per_lap;
    TrajectorySample s;
    s.t = period * k / per_lap;
    s.x = makeState(Vec3(radius * std::cos(a), radius * std::sin(a), 1.0), identityQuat(), Vec3::Zero());
    s.u = makeInput(Vec3::Zero(), 9.81);
    trajectory.samples.push_back(s);
  }
  addTrajectory(log, trajectory);
  const double laps = 2.55;
  for (int i = 0; i <= static_cast<int>(laps * period / 0.01); ++i) {
    const double tau = i * 0.01;
    const double a = tau * speed / radius;
    addTruth(log, 10.0 + tau, Vec3(1.02 * radius * std::cos(a), 1.02 * radius * std::sin(a), 1.0));
    if (i % 2) continue;
    const double k = std::fmod(tau / period * per_lap, per_lap);
    const int index = std::max(1, static_cast<int>(std::ceil(k)));
    addReference(log, 10.0 + tau, index, k - (index - 1), ReferenceMode::kTemporal);
  }
  const auto reports = analysis::analyzePathTracking(log);
  ASSERT_EQ(reports.size(), 1u);
  const auto& r = reports[0];
  EXPECT_FALSE(r.completed);
  EXPECT_NEAR(r.laps, laps, 0.01);
  EXPECT_EQ(r.samples_passed, 35 + 36 + 20);  // sample 0 counts from the second lap on; 19.8 of lap 3
  EXPECT_TRUE(r.skipped.empty());
  // 2 cm outside a polygon inscribed in the circle: between 2 cm (at the samples) and
  // 2 cm + the sagitta 1 - cos(5 deg) = 3.8 mm.
  EXPECT_GE(r.path_error_max, 0.02 - 1e-9);
  EXPECT_LE(r.path_error_max, 0.02 + radius * (1.0 - std::cos(M_PI / per_lap)) + 1e-6);
}

TEST(PathTracking, SaturationAndThrustLimits) {
  logger::FlightLog log;
  addTrajectory(log, makeTrajectory(lPath, 4.0, 0.1, ReferenceMode::kSpatial));
  for (int i = 0; i < 100; ++i) {
    const double t = 10.0 + 0.01 * i;
    addTruth(log, t, lPath(0.01 * i));
    referenceAt(log, t, 0.01 * i, 41, ReferenceMode::kSpatial);
    // 10 rate-clipped, 5 thrust-clipped to c_max (2 of them both) from demands above it, one NaN.
    const bool thrust_clipped = i >= 8 && i < 13;
    const int8_t saturated = static_cast<int8_t>((i < 10 ? 1 : 0) | (thrust_clipped ? 2 : 0));
    const double thrust = thrust_clipped ? 18.0 : (i == 60 ? std::nan("") : 9.81 + 0.01 * i);
    addCommand(log, t, thrust, saturated, thrust_clipped ? 18.5 + 0.1 * i : std::nan(""));
  }
  addCommand(log, 30.0, 25.0, 3);  // after the window: not counted
  analysis::PathTrackingOptions options;
  options.thrust_min = 2.0;
  options.thrust_max = 18.0;
  const auto reports = analysis::analyzePathTracking(log, options);
  ASSERT_EQ(reports.size(), 1u);
  const auto& r = reports[0];
  EXPECT_EQ(r.commands, 100);
  EXPECT_NEAR(r.saturation_percent, 13.0, 1e-9);
  EXPECT_NEAR(r.rate_saturation_percent, 10.0, 1e-9);
  EXPECT_NEAR(r.thrust_saturation_percent, 5.0, 1e-9);
  // The clipped commands never leave [c_min, c_max]: their demands did (5), and the NaN.
  EXPECT_EQ(r.thrust_violations, 6);
  EXPECT_NEAR(r.thrust_max, 18.0, 1e-12);
  EXPECT_NEAR(r.thrust_min, 9.81, 1e-12);
}

TEST(PathTracking, UntrackedTrajectoryIsNotReported) {
  logger::FlightLog log;
  addTrajectory(log, makeTrajectory(lPath, 4.0, 0.1, ReferenceMode::kSpatial));
  addTruth(log, 10.0, lPath(0.0));
  addReference(log, 10.0, 0, 0.0, ReferenceMode::kSetpoint, -1);  // the controller rejected it
  EXPECT_TRUE(analysis::analyzePathTracking(log).empty());
}

// The trajectory flown at 10 s (flyHeldAtCorner), tracked as `mode`.
mission::Scenario heldPathScenario(std::map<std::string, double> criteria, ReferenceMode mode = ReferenceMode::kSpatial) {
  mission::Scenario s;
  s.name = "synthetic";
  s.criteria = std::move(criteria);
  mission::ScenarioEvent e;
  e.at = 10.0;
  e.kind = mission::ScenarioEvent::Kind::kTrajectory;
  e.trajectory.tracking = mode;
  e.label = "held";
  s.events.push_back(e);
  return s;
}

TEST(PathTrackingCriteria, ChecksFollowTheScenario) {
  HeldAtCorner spatial = flyHeldAtCorner(ReferenceMode::kSpatial);
  HeldAtCorner temporal = flyHeldAtCorner(ReferenceMode::kTemporal);
  const std::map<std::string, double> spatial_criteria = {
      {"skip_radius", 0.25}, {"skipped_samples_max", 0}, {"path_return_error", 0.1}, {"path_return_time", 2.0},
      {"trajectory_completed", 1}};
  const auto a = analysis::analyzeFlight(spatial.log, heldPathScenario(spatial_criteria));
  analysis::writeSummary(a, std::cout);
  EXPECT_TRUE(a.passed());
  ASSERT_EQ(a.trajectories.size(), 1u);
  EXPECT_EQ(a.trajectories[0].label, "held");
  // The same criteria fail the temporal flight on its skipped samples.
  const auto b = analysis::analyzeFlight(temporal.log, heldPathScenario(spatial_criteria, ReferenceMode::kTemporal));
  EXPECT_FALSE(b.passed());
  bool skip_check_failed = false;
  for (const auto& c : b.checks) skip_check_failed |= (c.name == "skipped_samples_max[held]" && !c.pass);
  EXPECT_TRUE(skip_check_failed);
  const auto c = analysis::analyzeFlight(
      temporal.log, heldPathScenario({{"skip_radius", 0.25}, {"skipped_samples_min", 1}}, ReferenceMode::kTemporal));
  EXPECT_TRUE(c.passed());
  // A criterion about trajectories in a flight without one fails instead of passing vacuously.
  logger::FlightLog empty;
  addTruth(empty, 1.0, Vec3::Zero());
  EXPECT_FALSE(analysis::analyzeFlight(empty, heldPathScenario({{"path_error_max", 1.0}})).passed());
  // Thrust limits are needed to judge thrust.
  EXPECT_THROW(analysis::analyzeFlight(spatial.log, heldPathScenario({{"thrust_limit_violations_max", 0}})),
               std::invalid_argument);
  analysis::AnalysisOptions options;
  options.path.thrust_min = 2.0;
  options.path.thrust_max = 18.0;
  EXPECT_NO_THROW(analysis::analyzeFlight(spatial.log, heldPathScenario({{"thrust_limit_violations_max", 0}}), options));
}

// A path flown exactly for 1 s, then aborted by the guard into a hold (the reference leaves it for
// a setpoint with no new command) unless `aborted` is false, where it is flown to its end (and the
// reference stays on its last sample, as the controller's does).
logger::FlightLog flyGivenUpAfterOneSecond(bool aborted) {
  logger::FlightLog log;
  addTrajectory(log, makeTrajectory(lPath, 4.0, 0.1, ReferenceMode::kSpatial));
  for (int i = 0; i <= 500; ++i) {
    const double tau = i * 0.01;
    const bool holding = aborted && tau > 1.0;
    addTruth(log, 10.0 + tau, lPath(std::min(tau, holding ? 1.0 : 4.0)));
    if (holding) addReference(log, 10.0 + tau, 0, 0.0, ReferenceMode::kSetpoint, -1);  // the hold
    else referenceAt(log, 10.0 + tau, std::min(tau, 4.0), 41, ReferenceMode::kSpatial);
  }
  return log;
}

// The guard gave the path up after 1 s of its 4: the error of the second it flew (none) must not
// pass its checks. Every check of the path fails, naming the abort; flown to its end, they pass.
TEST(PathTrackingCriteria, APathTheGuardAbortedFailsItsChecksSayingSo) {
  const std::map<std::string, double> criteria = {{"path_error_rms", 0.1}, {"path_error_max", 0.3}};
  const auto aborted = analysis::analyzeFlight(flyGivenUpAfterOneSecond(true), heldPathScenario(criteria));
  ASSERT_EQ(aborted.trajectories.size(), 1u);
  EXPECT_NEAR(aborted.trajectories[0].aborted_at, 11.01, 1e-9);
  EXPECT_LT(aborted.trajectories[0].path_error_max, 1e-9) << "the part flown was flown exactly";
  EXPECT_FALSE(aborted.passed());
  for (const char* name : {"path_error_rms[held]", "path_error_max[held]"}) {
    const analysis::Check* check = nullptr;
    for (const auto& c : aborted.checks) check = c.name == name ? &c : check;
    ASSERT_NE(check, nullptr) << name;
    EXPECT_FALSE(check->pass) << name;
    EXPECT_EQ(check->note, "aborted into a hold by the guard at 11.01 s, 1.01 s into the path") << name;
  }
  const auto flown = analysis::analyzeFlight(flyGivenUpAfterOneSecond(false), heldPathScenario(criteria));
  EXPECT_TRUE(std::isnan(flown.trajectories[0].aborted_at));
  EXPECT_TRUE(flown.passed());
}

// A repeating mission (the soak's: a lap every 33 s) is judged lap by lap, each by its own event:
// a lap flown 20 cm off its path fails by its name, the good one beside it passes.
TEST(PathTrackingCriteria, EveryLapOfARepeatingMissionIsJudgedAndABadOneFailsByName) {
  logger::FlightLog log;
  mission::Scenario scenario;
  scenario.criteria = {{"path_error_rms", 0.1}, {"trajectory_completed", 1}};
  for (const auto& [start, seq, offset] : {std::tuple<double, int64_t, double>{10.0, 0, 0.0}, {30.0, 1, 0.2}}) {
    Trajectory lap = makeTrajectory(lPath, 4.0, 0.1, ReferenceMode::kSpatial);
    lap.seq = seq;
    lap.utime = lap.start_utime = micros(start);
    addTrajectory(log, lap);
    mission::ScenarioEvent e;
    e.at = start;
    e.kind = mission::ScenarioEvent::Kind::kTrajectory;
    e.label = "lap @" + std::to_string(static_cast<int>(start));
    scenario.events.push_back(e);
    for (int i = 0; i <= 500; ++i) {
      const double tau = i * 0.01, along = std::min(tau, 4.0);
      addTruth(log, start + tau, lPath(along) + Vec3(0.0, 0.0, offset));
      if (i % 2 == 0) referenceAt(log, start + tau, along, 41, ReferenceMode::kSpatial, seq);
    }
  }
  const analysis::FlightReport report = analysis::analyzeFlight(log, scenario);
  ASSERT_EQ(report.trajectories.size(), 2u);
  const analysis::Check* good = nullptr;
  const analysis::Check* bad = nullptr;
  for (const analysis::Check& c : report.checks) {
    if (c.name == "path_error_rms[lap @10]") good = &c;
    if (c.name == "path_error_rms[lap @30]") bad = &c;
  }
  ASSERT_NE(good, nullptr);
  ASSERT_NE(bad, nullptr);
  EXPECT_TRUE(good->pass);
  EXPECT_FALSE(bad->pass);
  EXPECT_NEAR(bad->value, 0.2, 1e-9);
  EXPECT_FALSE(report.passed());
}

}  // namespace
}  // namespace sdlqr
