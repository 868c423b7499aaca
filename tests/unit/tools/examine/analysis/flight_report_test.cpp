// The checks of a flight report on synthetic flights whose answers are known by construction:
// a jump that settles and one that does not, a pull the vehicle returns from and one it does not,
// a stack whose CPU and latency are fine or grossly worse than the machine's calibration, labels
// that follow the scenario's thresholds, the description of each kind of disturbance.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/analysis/flight_report.hpp"
#include "analysis_test_helpers.hpp"
#include "analysis_test_time.hpp"

namespace sdlqr {
namespace {

using ::sdlqr::test::micros;

using ::sdlqr::test::findCheck;

template <class T>
void add(logger::Series<T>& series, const T& message, int64_t receive_utime) {
  series.messages.push_back(message);
  series.receive_utime.push_back(receive_utime);
}

// A COMMAND to `position`, logged as received at its own time `t` [s].
void addCommand(logger::FlightLog& log, int64_t seq, double t, CommandType type, const Vec3& position) {
  Command c;
  c.seq = seq;
  c.utime = micros(t);
  c.command = type;
  c.position = position;
  add(log.command, c, c.utime);
}

// A vehicle at 1 m that is commanded 1 m along +x at t = 2 s and moves there along `x_of(t)`.
template <class XOf>
logger::FlightLog jumpFlight(XOf x_of, double duration = 8.0) {
  logger::FlightLog log;
  addCommand(log, 0, 0.5, CommandType::kTakeoff, Vec3(0, 0, 1));
  addCommand(log, 1, 2.0, CommandType::kGoto, Vec3(1, 0, 1));
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
  takeoff.at = 0.5;
  takeoff.command.command = CommandType::kTakeoff;
  takeoff.command.position = Vec3(0, 0, 1);
  jump.at = 2.0;
  jump.command.command = CommandType::kGoto;
  jump.command.position = Vec3(1, 0, 1);
  jump.label = "jump +x";
  s.events = {takeoff, jump};
  return s;
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

// Without a calibration a machine-dependent criterion is no check: it is listed first of the
// `listed` criteria not judged.
void expectNotJudged(const analysis::FlightReport& report, const std::string& key, size_t listed) {
  EXPECT_EQ(findCheck(report, key), nullptr);
  ASSERT_EQ(report.not_judged.size(), listed);
  EXPECT_EQ(report.not_judged[0].key, key);
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
  expectNotJudged(uncalibrated, "stack_cpu_relative_max", 2u);
}

// A flight whose controller ticks every 10 ms of simulation time (its own stamps are perfect)
// while the recorder receives its RATE_CMDs `wall_jitter_us` early and late in turn, and whose
// STATE_EST -> RATE_CMD latency is 100 us except every 50th command, which is `tail_us` late.
logger::FlightLog wallClockFlight(double wall_jitter_us, double tail_us) {
  logger::FlightLog log = jumpFlight(approach(0.4));
  for (const char* process : {"sdlqr-controller", "sdlqr-lowlevel"}) {
    logger::HeartbeatRecord hb;
    hb.process = process;
    hb.utime = micros(1.0);
    add(log.heartbeat, hb, micros(1.0));
  }
  for (int i = 0; i < 600; ++i) {
    StateEstimate e;
    e.seq = i;
    e.utime = micros(0.5 + 0.01 * i);
    const int64_t received = micros(100.0 + 0.01 * i);
    add(log.state_estimate, e, received);
    RateCommand c;
    c.seq = c.state_seq = i;
    c.utime = e.utime;
    const double late = 100.0 + (i % 50 == 0 ? tail_us : 0.0) + (i % 2 == 0 ? wall_jitter_us : -wall_jitter_us);
    add(log.rate_command, c, received + static_cast<int64_t>(late));
  }
  return log;
}

TEST(FlightReportChecks, WallClockPeriodIsJudgedAgainstTheCalibrationNotTheControllerStamps) {
  const auto scenario = scenarioWith({{"rate_cmd_wall_jitter_relative_max", 4.0}});
  analysis::AnalysisOptions options;
  options.calibration = calibration(20.0, 200.0);  // one-way median 100 us, one-way p99 300 us

  // 50 us either side of the 10 ms grid: |interval - 10 ms| = 100 us in the median, 1x the bus's
  // one-way median; a 3 ms tail on one command in fifty is reported, never judged.
  const auto fine = analysis::analyzeFlight(wallClockFlight(50.0, 3000.0), scenario, options);
  EXPECT_NEAR(fine.rate_cmd_jitter_ms.p99, 0.0, 1e-6);  // the stamps the controller set say nothing
  EXPECT_NEAR(fine.rate_cmd_wall_jitter_us.median, 100.0, 1.0);
  EXPECT_NEAR(fine.rate_cmd_wall_jitter_relative, 1.0, 0.02);
  EXPECT_GT(fine.rate_cmd_wall_jitter_p99_relative, 9.0);
  EXPECT_GT(fine.state_to_command_p99_relative, 9.0);
  EXPECT_TRUE(fine.passed());

  // A controller whose period swings 1 ms on the wall clock (10x the bus's one-way median) fails,
  // though its simulation-time stamps are exactly as perfect as before.
  const auto late = analysis::analyzeFlight(wallClockFlight(500.0, 0.0), scenario, options);
  EXPECT_NEAR(late.rate_cmd_jitter_ms.p99, 0.0, 1e-6);
  EXPECT_NEAR(late.rate_cmd_wall_jitter_relative, 10.0, 0.2);
  EXPECT_FALSE(findCheck(late, "rate_cmd_wall_jitter_relative_max")->pass);

  // The same flight on a machine whose bus is ten times slower: within its budget.
  options.calibration = calibration(20.0, 2000.0);
  EXPECT_TRUE(analysis::analyzeFlight(wallClockFlight(500.0, 0.0), scenario, options).passed());

  // Without a calibration: listed as not judged, never passed.
  const auto uncalibrated = analysis::analyzeFlight(wallClockFlight(500.0, 0.0), scenario);
  expectNotJudged(uncalibrated, "rate_cmd_wall_jitter_relative_max", 1u);
}

// The jump flight with RATE_CMD whose thrust demand was `demand` (clipped to [2, 18] m/s^2 as the
// controller does) and MOTOR_CMD whose first rotor gets `rotor` N (limits [0, 1.25] N).
logger::FlightLog saturatingFlight(double demand, double rotor) {
  logger::FlightLog log = jumpFlight(approach(0.4));
  for (int i = 0; i < 700; ++i) {
    const double t = 0.5 + 0.01 * i;
    RateCommand c;
    c.utime = micros(t);
    c.thrust_demand = t > 2.0 && t < 2.3 ? demand : 9.81;
    c.thrust = std::clamp(c.thrust_demand, 2.0, 18.0);
    add(log.rate_command, c, c.utime);
    MotorCommand m;
    m.utime = c.utime;
    m.mode = MotorMode::kRate;
    m.thrust = Vec4::Constant(0.625);
    if (t > 2.0 && t < 2.1) m.thrust[0] = rotor;
    add(log.motor_command, m, m.utime);
  }
  return log;
}

analysis::AnalysisOptions limitsOfTheTestVehicle() {
  analysis::AnalysisOptions options;
  options.path.thrust_min = 2.0;
  options.path.thrust_max = 18.0;
  options.rotor_thrust_min = 0.0;
  options.rotor_thrust_max = 1.25;
  return options;
}

TEST(FlightReportChecks, AControllerThatSaturatesFailsWhereTheSaturationHappens) {
  const auto scenario = scenarioWith({{"thrust_demand_outside_max", 0}, {"rotor_at_limit_max", 0}});
  const auto options = limitsOfTheTestVehicle();
  const auto fine = analysis::analyzeFlight(saturatingFlight(15.0, 1.0), scenario, options);
  EXPECT_EQ(fine.saturation.thrust_demand_outside, 0);
  EXPECT_EQ(fine.saturation.rotor_at_limit, 0);
  EXPECT_GT(fine.saturation.motor_commands, 600);
  EXPECT_TRUE(fine.passed());

  // The law asked for 25 m/s^2 for 0.3 s; every command sent was clipped to 18, inside the limits.
  const auto clipped = analysis::analyzeFlight(saturatingFlight(25.0, 1.0), scenario, options);
  EXPECT_EQ(clipped.saturation.thrust_demand_outside, 29);
  EXPECT_NEAR(clipped.saturation.thrust_demand_max, 25.0, 1e-12);
  EXPECT_FALSE(findCheck(clipped, "thrust_demand_outside_max")->pass);
  EXPECT_TRUE(findCheck(clipped, "rotor_at_limit_max")->pass);

  // A rotor the mixer left at full thrust (or at zero) for 0.1 s.
  for (const double rotor : {1.25, 0.0}) {
    const auto at_limit = analysis::analyzeFlight(saturatingFlight(15.0, rotor), scenario, options);
    EXPECT_EQ(at_limit.saturation.rotor_at_limit, 9) << rotor;
    EXPECT_FALSE(findCheck(at_limit, "rotor_at_limit_max")->pass) << rotor;
  }

  // A log without the messages to count (no MOTOR_CMD recorded) fails instead of passing on zero.
  logger::FlightLog no_motors = saturatingFlight(15.0, 1.0);
  no_motors.motor_command = {};
  EXPECT_FALSE(findCheck(analysis::analyzeFlight(no_motors, scenario, options), "rotor_at_limit_max")->pass);

  // Without the vehicle's limits the criteria cannot be judged: an error, not a pass.
  EXPECT_THROW(analysis::analyzeFlight(saturatingFlight(25.0, 1.0), scenario), std::invalid_argument);
}

// On the ground at the origin, TAKEOFF to 1 m at 0.5 s; the vehicle climbs to `reached` and the
// controller's own REFERENCE says `reached` too (a controller that mistook the height).
logger::FlightLog takeoffFlight(double reached) {
  logger::FlightLog log;
  addCommand(log, 0, 0.5, CommandType::kTakeoff, Vec3(0, 0, 1));
  for (double t = 0.0; t <= 6.0; t += 0.004) {
    SimTruth s;
    s.utime = micros(t);
    const double z = t < 0.5 ? 0.0 : reached * (1.0 - std::exp(-(t - 0.5) / 0.5));
    s.on_ground = z < 1e-3;
    s.position = Vec3(0.0, 0.0, z);
    add(log.sim_truth, s, s.utime);
    Reference r;
    r.utime = s.utime;
    r.x = makeState(Vec3(0, 0, reached), identityQuat(), Vec3::Zero());
    add(log.reference, r, r.utime);
  }
  return log;
}

TEST(FlightReportChecks, TheTakeoffIsJudgedAgainstTheCommandedHeightNotTheControllersReference) {
  mission::Scenario scenario = scenarioWith({{"jump_settle_error", 0.05}, {"takeoff_settle_time", 3.0},
                                             {"hover_error", 0.05}});
  scenario.events.pop_back();  // the take-off only
  const auto good = analysis::analyzeFlight(takeoffFlight(1.0), scenario);
  ASSERT_EQ(good.setpoints.size(), 1u);
  EXPECT_NEAR(good.setpoints[0].size, 1.0, 1e-9);
  EXPECT_NEAR(good.setpoints[0].settle_time, 0.5 * std::log(1.0 / 0.05), 0.01);
  EXPECT_TRUE(good.passed());
  // 10 cm short of the command, on its own reference: fails both.
  const auto short_of_it = analysis::analyzeFlight(takeoffFlight(0.9), scenario);
  EXPECT_NEAR(short_of_it.setpoints[0].to[2], 1.0, 1e-9);
  EXPECT_FALSE(findCheck(short_of_it, "takeoff_settle_time[takeoff]")->pass);
  EXPECT_FALSE(findCheck(short_of_it, "hover_error[takeoff]")->pass);
}

TEST(FlightReportSummary, EachDisturbanceIsDescribedByWhatItWas) {
  logger::FlightLog log = jumpFlight(approach(0.4));
  mission::Scenario scenario = scenarioWith({});
  auto addPull = [&](double at, const Disturbance& d) {
    Disturbance sent = d;
    sent.utime = sent.start_utime = micros(at);
    sent.seq = static_cast<int64_t>(log.disturbance.size());
    add(log.disturbance, sent, sent.utime);
    mission::ScenarioEvent e;
    e.at = at;
    e.kind = mission::ScenarioEvent::Kind::kDisturbance;
    e.disturbance = d;
    scenario.events.push_back(e);
  };
  Disturbance kick;
  kick.torque = Vec3(0.05, 0.0, 0.0);
  kick.duration = 0.15;
  addPull(5.0, kick);
  Disturbance spring;
  spring.mode = DisturbanceMode::kHold;
  spring.hold_position = Vec3(1.0, 0.5, 1.0);
  spring.hold_stiffness = 40.0;
  spring.duration = 0.5;
  addPull(6.0, spring);
  Disturbance pull;
  pull.force = Vec3(0.0, 2.0, 0.0);
  pull.duration = 0.5;
  addPull(7.0, pull);
  const auto report = analysis::analyzeFlight(log, scenario);
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
  r.saturation.thrust_demand_outside = r.saturation.rotor_at_limit = 1;
  r.saturation.commands = r.saturation.motor_commands = 100;
  r.stack_cpu_relative = r.state_to_command_relative = 1.0;
  r.recovery = analysis::RecoveryReport{};
  r.recovery->detect_delay = r.recovery->level_time = r.recovery->height_lost = r.recovery->settle_time = 1.0;
  r.trajectory_aborts = 1;
  r.state_to_command_p99_relative = r.rate_cmd_wall_jitter_relative = r.rate_cmd_wall_jitter_p99_relative = 1.0;
  r.processes.push_back({});
  r.calibration = calibration(20.0, 140.0);
  return r;
}

TEST(CriteriaTable, EveryFlightCriterionFailsBeyondItsLimitAndPassesWithin) {
  for (const analysis::CriterionSpec& spec : analysis::criteria()) {
    if (spec.scope != analysis::Scope::kFlight || spec.always) continue;
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
