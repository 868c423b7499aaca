// The checks of a flight report on synthetic flights whose answers are known by construction:
// a jump that settles and one that does not, a pull the vehicle returns from and one it does not,
// a stack whose CPU and latency are fine or grossly worse than the machine's calibration, labels
// that follow the scenario's thresholds, the description of each kind of disturbance.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/analysis/flight_report.hpp"

namespace sdlqr {
namespace {

int64_t micros(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }

template <class T>
void add(logger::Series<T>& series, const T& message, int64_t receive_utime) {
  series.messages.push_back(message);
  series.receive_utime.push_back(receive_utime);
}

// A vehicle at 1 m that is commanded 1 m along +x at t = 2 s and moves there along `x_of(t)`.
template <class XOf>
logger::FlightLog jumpFlight(XOf x_of, double duration = 8.0) {
  logger::FlightLog log;
  Command takeoff;
  takeoff.seq = 0;
  takeoff.utime = micros(0.5);
  takeoff.command = CommandType::kTakeoff;
  takeoff.position = Vec3(0, 0, 1);
  add(log.command, takeoff, takeoff.utime);
  Command jump;
  jump.seq = 1;
  jump.utime = micros(2.0);
  jump.command = CommandType::kGoto;
  jump.position = Vec3(1, 0, 1);
  add(log.command, jump, jump.utime);
  for (double t = 0.0; t <= duration; t += 0.004) {
    SimTruth s;
    s.utime = micros(t);
    s.on_ground = false;
    s.position = Vec3(t < 2.0 ? 0.0 : x_of(t - 2.0), 0.0, 1.0);
    add(log.sim_truth, s, s.utime);
    Reference r;
    r.utime = s.utime;
    r.x = makeState(t < 2.0 ? Vec3(0, 0, 1) : Vec3(1, 0, 1), identityQuat(), Vec3::Zero());
    add(log.reference, r, r.utime);
  }
  return log;
}

mission::Scenario scenarioWith(std::map<std::string, double> criteria) {
  mission::Scenario s;
  s.name = "synthetic";
  s.criteria = std::move(criteria);
  mission::ScenarioEvent takeoff, jump;
  takeoff.kind = jump.kind = mission::ScenarioEvent::Kind::kCommand;
  takeoff.command.command = CommandType::kTakeoff;
  jump.command.command = CommandType::kGoto;
  jump.label = "jump +x";
  s.events = {takeoff, jump};
  return s;
}

const analysis::Check* findCheck(const analysis::FlightReport& report, const std::string& name) {
  for (const analysis::Check& c : report.checks) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

// First-order approach to 1 m with time constant tau.
auto approach(double tau) {
  return [tau](double t) { return 1.0 - std::exp(-t / tau); };
}

TEST(FlightReportChecks, AJumpThatSettlesPassesAndOneThatStaysOffFails) {
  const auto criteria = std::map<std::string, double>{{"jump_settle_error", 0.05}, {"jump_settle_time", 3.0}};
  const auto good = analysis::analyzeFlight(jumpFlight(approach(0.4)), scenarioWith(criteria));
  const analysis::Check* settled = findCheck(good, "jump_settle_time[jump +x]");
  ASSERT_NE(settled, nullptr);
  EXPECT_TRUE(settled->pass);
  EXPECT_NEAR(settled->value, 0.4 * std::log(1.0 / 0.05), 0.01);  // e^{-t/tau} = 0.05
  // Stuck 10 cm short: never below 5 cm.
  const auto bad = analysis::analyzeFlight(jumpFlight([](double t) { return 0.9 * (1.0 - std::exp(-t / 0.4)); }),
                                           scenarioWith(criteria));
  EXPECT_FALSE(findCheck(bad, "jump_settle_time[jump +x]")->pass);
  EXPECT_FALSE(bad.passed());
}

TEST(FlightReportChecks, OvershootBeyondTheLimitFails) {
  const auto criteria = std::map<std::string, double>{{"jump_max_overshoot", 0.2}};
  // Damped oscillation around 1 m, first peak 1.3 m.
  const auto ringing = [](double t) { return 1.0 - std::exp(-t / 1.0) * std::cos(6.0 * t) + 0.0 * t; };
  const auto bad = analysis::analyzeFlight(jumpFlight(ringing), scenarioWith(criteria));
  const analysis::Check* overshoot = findCheck(bad, "jump_max_overshoot[jump +x]");
  ASSERT_NE(overshoot, nullptr);
  EXPECT_GT(overshoot->value, 0.2);
  EXPECT_FALSE(overshoot->pass);
  EXPECT_TRUE(findCheck(analysis::analyzeFlight(jumpFlight(approach(0.4)), scenarioWith(criteria)),
                        "jump_max_overshoot[jump +x]")->pass);
}

TEST(FlightReportChecks, LabelsFollowTheScenarioThreshold) {
  const auto report = analysis::analyzeFlight(jumpFlight(approach(0.4)),
                                              scenarioWith({{"jump_settle_error", 0.1}, {"jump_settle_time", 3.0}}));
  const analysis::Check* settled = findCheck(report, "jump_settle_time[jump +x]");
  ASSERT_NE(settled, nullptr);
  EXPECT_EQ(settled->description, "settle time: error below 10 cm and staying");
  EXPECT_NEAR(settled->value, 0.4 * std::log(1.0 / 0.1), 0.01);
  std::ostringstream summary;
  analysis::writeSummary(report, summary);
  EXPECT_NE(summary.str().find("settle (<10 cm)"), std::string::npos) << summary.str();
}

TEST(FlightReportChecks, AnUnknownCriterionNamesItsKey) {
  try {
    analysis::analyzeFlight(jumpFlight(approach(0.4)), scenarioWith({{"jump_setle_time", 3.0}}));
    FAIL() << "accepted a misspelled criterion";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("criteria.jump_setle_time"), std::string::npos) << e.what();
  }
}

// Heartbeats of the five flight processes at `cpu_each` % and STATE_EST -> RATE_CMD pairs
// `latency_us` apart at the recorder.
logger::FlightLog busFlight(double cpu_each, double latency_us) {
  logger::FlightLog log = jumpFlight(approach(0.4));
  for (const char* process : {"sdlqr-sim", "sdlqr-estimator", "sdlqr-gains", "sdlqr-controller", "sdlqr-lowlevel"}) {
    for (double t = 1.0; t <= 7.0; t += 1.0) {
      logger::HeartbeatRecord hb;
      hb.process = process;
      hb.utime = micros(t);
      hb.cpu_percent = cpu_each;
      add(log.heartbeat, hb, micros(t));
    }
  }
  for (int i = 0; i < 100; ++i) {
    StateEstimate e;
    e.seq = i;
    e.utime = micros(1.0 + 0.01 * i);
    add(log.state_estimate, e, micros(100.0 + 0.01 * i));
    RateCommand c;
    c.seq = i;
    c.state_seq = i;
    c.utime = e.utime;
    add(log.rate_command, c, micros(100.0 + 0.01 * i) + static_cast<int64_t>(latency_us));
  }
  return log;
}

calibrate::Calibration calibration(double cpu_percent, double rtt_median_us) {
  calibrate::Calibration c;
  c.echo_rate_hz = 1000.0;
  c.pings = c.pongs = 1500;
  c.rtt_median_us = rtt_median_us;
  c.rtt_p99_us = 3.0 * rtt_median_us;
  c.cpu_percent = cpu_percent;
  c.window_s = 1.5;
  return c;
}

TEST(FlightReportChecks, MachineFiguresAreJudgedOnlyAgainstTheCalibration) {
  const auto scenario =
      scenarioWith({{"stack_cpu_relative_max", 4.0}, {"state_to_command_latency_relative_max", 10.0}});
  analysis::AnalysisOptions options;
  options.calibration = calibration(20.0, 140.0);  // one-way median 70 us

  // 5 x 8 % = 40 % of a core on a machine whose ping/pong costs 20 %: 2x. Latency 150 us: 2.1x.
  const auto fine = analysis::analyzeFlight(busFlight(8.0, 150.0), scenario, options);
  EXPECT_NEAR(fine.stack_cpu_relative, 2.0, 1e-9);
  EXPECT_NEAR(fine.state_to_command_relative, 150.0 / 70.0, 1e-9);
  EXPECT_TRUE(fine.passed());

  // The same stack on a machine twice as slow, measured as twice as slow: still 2x, still passes.
  options.calibration = calibration(40.0, 280.0);
  EXPECT_TRUE(analysis::analyzeFlight(busFlight(16.0, 300.0), scenario, options).passed());

  // A stack burning 5x the machine's ping/pong, a controller 1 ms late: both fail.
  options.calibration = calibration(20.0, 140.0);
  const auto heavy = analysis::analyzeFlight(busFlight(20.0, 1000.0), scenario, options);
  EXPECT_FALSE(findCheck(heavy, "stack_cpu_relative_max")->pass);
  EXPECT_FALSE(findCheck(heavy, "state_to_command_latency_relative_max")->pass);

  // Without a calibration nothing machine-dependent is judged; it is listed, not passed.
  const auto uncalibrated = analysis::analyzeFlight(busFlight(20.0, 1000.0), scenario);
  EXPECT_EQ(findCheck(uncalibrated, "stack_cpu_relative_max"), nullptr);
  ASSERT_EQ(uncalibrated.not_judged.size(), 2u);
  EXPECT_EQ(uncalibrated.not_judged[0].key, "stack_cpu_relative_max");
}

TEST(FlightReportSummary, EachDisturbanceIsDescribedByWhatItWas) {
  logger::FlightLog log = jumpFlight(approach(0.4));
  Disturbance kick;
  kick.utime = kick.start_utime = micros(5.0);
  kick.torque = Vec3(0.05, 0.0, 0.0);
  kick.duration = 0.15;
  add(log.disturbance, kick, kick.utime);
  Disturbance spring;
  spring.utime = spring.start_utime = micros(6.0);
  spring.mode = DisturbanceMode::kHold;
  spring.hold_position = Vec3(1.0, 0.5, 1.0);
  spring.hold_stiffness = 40.0;
  spring.duration = 0.5;
  add(log.disturbance, spring, spring.utime);
  Disturbance pull;
  pull.utime = pull.start_utime = micros(7.0);
  pull.force = Vec3(0.0, 2.0, 0.0);
  pull.duration = 0.5;
  add(log.disturbance, pull, pull.utime);
  const auto report = analysis::analyzeFlight(log, scenarioWith({}));
  std::ostringstream summary;
  analysis::writeSummary(report, summary);
  const std::string text = summary.str();
  EXPECT_NE(text.find("torque (0.05, 0.00, 0.00) N m for 0.15 s"), std::string::npos) << text;
  EXPECT_NE(text.find("spring 40 N/m holding at (1.00, 0.50, 1.00) m for 0.50 s"), std::string::npos) << text;
  EXPECT_NE(text.find("force (0.00, 2.00, 0.00) N for 0.50 s"), std::string::npos) << text;
  EXPECT_EQ(text.find("0.0 N for 0.15 s"), std::string::npos) << text;
}

// Every flight criterion of the table can fail and can pass: a report whose every figure is 1
// fails each criterion whose limit lies on the wrong side of 1 and passes it on the right side.
analysis::FlightReport reportOfOnes() {
  analysis::FlightReport r;
  r.nonfinite = 1;
  r.crashed = true;
  r.estimator.position_rms = r.estimator.attitude_rms_deg = 1.0;
  r.gains_rate_hz = r.rate_cmd_rate_hz = r.state_est_rate_hz = 1.0;
  r.max_tilt_deg = r.touchdown_speed = 1.0;
  r.rate_cmd_jitter_ms.p99 = 1.0;
  r.stack_cpu_relative = r.state_to_command_relative = 1.0;
  r.recovery = analysis::RecoveryReport{};
  r.recovery->detect_delay = r.recovery->level_time = r.recovery->height_lost = r.recovery->settle_time = 1.0;
  r.trajectory_aborts = 1;
  r.processes.push_back({});
  r.calibration = calibration(20.0, 140.0);
  return r;
}

TEST(CriteriaTable, EveryFlightCriterionFailsBeyondItsLimitAndPassesWithin) {
  for (const analysis::CriterionSpec& spec : analysis::criteria()) {
    if (spec.scope != analysis::Scope::kFlight || spec.key == "nonfinite_messages" || spec.key == "crashed") continue;
    for (const bool beyond : {true, false}) {
      analysis::FlightReport report = reportOfOnes();
      ASSERT_EQ(spec.of_flight(report), 1.0) << spec.key << ": the test does not set this figure";
      const bool at_most = spec.bound == analysis::Bound::kAtMost;
      mission::Scenario scenario;
      scenario.criteria[std::string(spec.key)] = at_most == beyond ? 0.5 : 1.5;
      analysis::judgeCriteria(report, scenario, analysis::AnalysisOptions{});
      const analysis::Check* check = findCheck(report, std::string(spec.key));
      ASSERT_NE(check, nullptr) << spec.key;
      EXPECT_EQ(check->pass, !beyond) << spec.key << " value " << check->value << " limit " << check->limit;
    }
  }
  // The two checks every flight gets fail on a NaN message and on a crash.
  analysis::FlightReport report = reportOfOnes();
  analysis::judgeCriteria(report, mission::Scenario{}, analysis::AnalysisOptions{});
  EXPECT_FALSE(findCheck(report, "nonfinite_messages")->pass);
  EXPECT_FALSE(findCheck(report, "crashed")->pass);
}

// Without an airborne start or a throw there is no recovery: its criteria fail, never pass empty.
TEST(CriteriaTable, RecoveryCriteriaFailWithoutARecovery) {
  analysis::FlightReport report = reportOfOnes();
  report.recovery.reset();
  mission::Scenario scenario;
  for (const char* key : {"recovery_level_time", "recovery_height_lost", "recovery_settle_time", "throw_detect_delay"}) {
    scenario.criteria[key] = 100.0;
  }
  analysis::judgeCriteria(report, scenario, analysis::AnalysisOptions{});
  for (const char* key : {"recovery_level_time", "recovery_height_lost", "recovery_settle_time", "throw_detect_delay"}) {
    ASSERT_NE(findCheck(report, key), nullptr) << key;
    EXPECT_FALSE(findCheck(report, key)->pass) << key;
  }
}

}  // namespace
}  // namespace sdlqr
