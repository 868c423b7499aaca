// The checks of a flight come from its scenario's events, not from what its log happens to hold:
// a flight flown as scheduled passes with a check per event; an event whose message is not in the
// log fails the checks of that event, each naming it, and no other event takes its name; a report
// that judged nothing fails.

#include <gtest/gtest.h>

#include <sstream>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/analysis/scenario_events.hpp"
#include "analysis_test_helpers.hpp"
#include "analysis_test_time.hpp"

namespace sdlqr {
namespace {

using ::sdlqr::test::findCheck;
using ::sdlqr::test::micros;

mission::ScenarioEvent commandAt(double at, CommandType type, const Vec3& position, const char* label) {
  mission::ScenarioEvent e;
  e.at = at;
  e.kind = mission::ScenarioEvent::Kind::kCommand;
  e.command.command = type;
  e.command.position = position;
  e.label = label;
  return e;
}

// Arm at 0.1 s, take off to 1 m at 0.3 s, jump +x at 2 s, jump +y at 5 s, a 2 N pull along +y at
// 8 s for 0.5 s, land at 11 s.
mission::Scenario scheduled() {
  mission::Scenario s;
  s.name = "scheduled";
  s.duration = 14.0;
  s.events.push_back(commandAt(0.1, CommandType::kArm, Vec3::Zero(), ""));
  s.events.push_back(commandAt(0.3, CommandType::kTakeoff, Vec3(0, 0, 1), ""));
  s.events.push_back(commandAt(2.0, CommandType::kGoto, Vec3(1, 0, 1), "jump +x"));
  s.events.push_back(commandAt(5.0, CommandType::kGoto, Vec3(1, 1, 1), "jump +y"));
  mission::ScenarioEvent pull;
  pull.at = 8.0;
  pull.kind = mission::ScenarioEvent::Kind::kDisturbance;
  pull.disturbance.force = Vec3(0, 2, 0);
  pull.disturbance.duration = 0.5;
  pull.label = "pull +y";
  s.events.push_back(pull);
  s.events.push_back(commandAt(11.0, CommandType::kLand, Vec3::Zero(), ""));
  s.criteria = {{"jump_settle_time", 3.0}, {"hover_error", 0.05}, {"pull_return_time", 3.0},
                {"touchdown_speed_max", 1.0}};
  return s;
}

template <class T>
void record(logger::Series<T>& series, const T& message) {
  series.messages.push_back(message);
  series.receive_utime.push_back(message.utime);
}

// The flight the scenario asks for, flown at once: up at 0.35 s, every setpoint reached 50 ms after
// its command and held exactly, the pull taking the vehicle 0.2 m aside until its release, down at 0.4 m/s after LAND (touchdown at
// 13.5 s).
// `touchdown` false: still airborne when the log ends.
logger::FlightLog flownAsScheduled(const mission::Scenario& s, bool touchdown = true) {
  logger::FlightLog log;
  int64_t seq = 0;
  for (const mission::ScenarioEvent& e : s.events) {
    if (e.kind == mission::ScenarioEvent::Kind::kCommand) {
      Command c = e.command;
      c.utime = micros(e.at);
      c.seq = seq++;
      record(log.command, c);
    } else if (e.kind == mission::ScenarioEvent::Kind::kDisturbance) {
      Disturbance d = e.disturbance;
      d.utime = d.start_utime = micros(e.at);
      record(log.disturbance, d);
    }
  }
  for (int k = 0; k * 0.004 <= s.duration; ++k) {
    const double t = k * 0.004;
    const Vec3 setpoint = t < 2.0 ? Vec3(0, 0, 1) : t < 5.0 ? Vec3(1, 0, 1) : Vec3(1, 1, 1);
    const double lagged = t - 0.05;  // the vehicle follows 50 ms after each event
    SimTruth truth;
    truth.utime = micros(t);
    truth.position = (lagged < 2.0 ? Vec3(0, 0, 1) : lagged < 5.0 ? Vec3(1, 0, 1) : Vec3(1, 1, 1)) +
                     (lagged >= 8.0 && lagged < 8.5 ? Vec3(0, 0.2, 0) : Vec3::Zero());
    if (t >= 11.0) {
      truth.position[2] = std::max(0.0, 1.0 - 0.4 * (t - 11.0));
      truth.velocity[2] = -0.4;
    }
    if (!touchdown) truth.position[2] = std::max(truth.position[2], 0.5);
    if (t < 0.35) truth.position[2] = 0.0;
    truth.on_ground = truth.position[2] <= 0.0;
    record(log.sim_truth, truth);
    Reference r;
    r.utime = truth.utime;
    r.x = makeState(setpoint, identityQuat(), Vec3::Zero());
    record(log.reference, r);
  }
  return log;
}

// Every copy (first send and re-sends) of the command of this seq.
void dropCommand(logger::FlightLog& log, int64_t seq) {
  logger::Series<Command> kept;
  for (const Command& c : log.command.messages) {
    if (c.seq != seq) record(kept, c);
  }
  log.command = kept;
}

TEST(ScenarioEvents, AFlightFlownAsScheduledPassesWithACheckPerEvent) {
  const mission::Scenario scenario = scheduled();
  const analysis::FlightReport report = analysis::analyzeFlight(flownAsScheduled(scenario), scenario);
  std::ostringstream summary;
  analysis::writeSummary(report, summary);
  EXPECT_TRUE(report.passed()) << summary.str();
  for (const char* label : {"arm", "takeoff", "jump +x", "jump +y", "pull +y", "land"}) {
    const analysis::Check* check = findCheck(report, std::string("event_in_log[") + label + "]");
    ASSERT_NE(check, nullptr) << label;
    EXPECT_TRUE(check->pass) << label;
  }
  for (const char* name : {"jump_settle_time[jump +x]", "jump_settle_time[jump +y]", "hover_error[takeoff]",
                           "pull_return_time[pull +y]", "touchdown_speed_max[land]"}) {
    ASSERT_NE(findCheck(report, name), nullptr) << name;
    EXPECT_TRUE(findCheck(report, name)->pass) << name;
  }
  EXPECT_NEAR(findCheck(report, "touchdown_speed_max[land]")->value, 0.4, 1e-9);
}

TEST(ScenarioEvents, APullWhoseDisturbanceIsNotInTheLogFailsNamingIt) {
  const mission::Scenario scenario = scheduled();
  logger::FlightLog log = flownAsScheduled(scenario);
  log.disturbance = {};
  const analysis::FlightReport report = analysis::analyzeFlight(log, scenario);
  EXPECT_FALSE(report.passed());
  const std::string why = "pull +y at 8.0 s: DISTURBANCE not in the log";
  for (const char* name : {"event_in_log[pull +y]", "pull_return_time[pull +y]"}) {
    const analysis::Check* check = findCheck(report, name);
    ASSERT_NE(check, nullptr) << name;
    EXPECT_FALSE(check->pass) << name;
    EXPECT_EQ(check->note, why) << name;
  }
  std::ostringstream summary;
  analysis::writeSummary(report, summary);
  EXPECT_NE(summary.str().find("FAILED event_in_log[pull +y]: 0 (limit >= 1): " + why), std::string::npos)
      << summary.str();
  // Every other event is in the log.
  for (const analysis::Check& c : report.checks) {
    if (c.key == "event_in_log" && c.window != "pull +y") {
      EXPECT_TRUE(c.pass) << c.name;
    }
  }
}

TEST(ScenarioEvents, AJumpWhoseCommandIsNotInTheLogFailsAndNoOtherJumpTakesItsName) {
  const mission::Scenario scenario = scheduled();
  logger::FlightLog log = flownAsScheduled(scenario);
  dropCommand(log, 2);  // jump +x
  const analysis::FlightReport report = analysis::analyzeFlight(log, scenario);
  EXPECT_FALSE(report.passed());
  const analysis::Check* settle = findCheck(report, "jump_settle_time[jump +x]");
  ASSERT_NE(settle, nullptr);
  EXPECT_FALSE(settle->pass);
  EXPECT_EQ(settle->note, "jump +x at 2.0 s: COMMAND not in the log");
  EXPECT_FALSE(findCheck(report, "event_in_log[jump +x]")->pass);
  // jump +y is still judged as jump +y, from its own command at 5 s.
  const analysis::Check* next = findCheck(report, "jump_settle_time[jump +y]");
  ASSERT_NE(next, nullptr);
  EXPECT_TRUE(next->pass);
  for (const analysis::SetpointWindow& w : report.setpoints) {
    if (w.label == "jump +y") {
      EXPECT_DOUBLE_EQ(w.start, 5.0);
    }
  }
}

TEST(ScenarioEvents, ACommandWhoseFirstCopyWasLostIsFoundInItsResendLate) {
  const mission::Scenario scenario = scheduled();
  logger::FlightLog log = flownAsScheduled(scenario);
  Command resend = log.command[3];  // jump +y, sent at 5 s; the mission sends it again each second
  dropCommand(log, 3);
  resend.utime = micros(6.0);
  record(log.command, resend);
  const analysis::FlightReport report = analysis::analyzeFlight(log, scenario);
  const analysis::Check* event = findCheck(report, "event_in_log[jump +y]");
  ASSERT_NE(event, nullptr);
  EXPECT_TRUE(event->pass);
  EXPECT_EQ(event->note, "jump +y at 5.0 s: COMMAND in the log at 6.00 s");
}

TEST(ScenarioEvents, ALandingThatNeverTouchedDownFails) {
  const mission::Scenario scenario = scheduled();
  const analysis::FlightReport report = analysis::analyzeFlight(flownAsScheduled(scenario, false), scenario);
  const analysis::Check* touchdown = findCheck(report, "touchdown_speed_max[land]");
  ASSERT_NE(touchdown, nullptr);
  EXPECT_FALSE(touchdown->pass);
  EXPECT_TRUE(std::isnan(touchdown->value));
}

TEST(ScenarioEvents, ATrajectoryNotInTheLogOrNeverTrackedFailsItsCriteria) {
  mission::Scenario scenario = scheduled();
  mission::ScenarioEvent lap;
  lap.at = 9.0;
  lap.kind = mission::ScenarioEvent::Kind::kTrajectory;
  scenario.events.insert(scenario.events.end() - 1, lap);
  scenario.criteria = {{"path_error_rms", 0.1}};
  logger::FlightLog log = flownAsScheduled(scenario);
  analysis::FlightReport report = analysis::analyzeFlight(log, scenario);
  const analysis::Check* path = findCheck(report, "path_error_rms[trajectory 1]");
  ASSERT_NE(path, nullptr);
  EXPECT_FALSE(path->pass);
  EXPECT_EQ(path->note, "trajectory 1 at 9.0 s: TRAJECTORY not in the log");
  // In the log, but the controller never followed it (no REFERENCE of its seq).
  Trajectory uploaded;
  uploaded.utime = uploaded.start_utime = micros(9.0);
  uploaded.samples.resize(2);
  uploaded.samples[1].t = 1.0;
  record(log.trajectory, uploaded);
  report = analysis::analyzeFlight(log, scenario);
  path = findCheck(report, "path_error_rms[trajectory 1]");
  ASSERT_NE(path, nullptr);
  EXPECT_FALSE(path->pass);
  EXPECT_EQ(path->note, "trajectory 1 at 9.0 s: TRAJECTORY in the log at 9.00 s, never tracked by the controller");
}

TEST(ScenarioEvents, ACriterionOfWindowsTheScenarioNeverPlaysFails) {
  mission::Scenario scenario = scheduled();
  scenario.events.erase(scenario.events.begin() + 2, scenario.events.begin() + 4);  // no jump left
  scenario.criteria = {{"jump_settle_time", 3.0}};
  const analysis::FlightReport report = analysis::analyzeFlight(flownAsScheduled(scenario), scenario);
  const analysis::Check* settle = findCheck(report, "jump_settle_time");
  ASSERT_NE(settle, nullptr);
  EXPECT_FALSE(settle->pass);
  EXPECT_EQ(settle->note, "the scenario has no jump (goto) for it to judge");
}

TEST(ScenarioEvents, AReportThatJudgedNothingFails) {
  EXPECT_FALSE(analysis::FlightReport{}.passed());
  std::ostringstream summary;
  analysis::writeSummary(analysis::FlightReport{}, summary);
  EXPECT_NE(summary.str().find("FAILED: no check judged this flight"), std::string::npos) << summary.str();
}

TEST(ScenarioEvents, LabelsAreUniqueAndAThrowIsExpected) {
  mission::Scenario scenario;
  scenario.events.push_back(commandAt(2.0, CommandType::kGoto, Vec3(1, 0, 1), ""));
  scenario.events.push_back(commandAt(5.0, CommandType::kGoto, Vec3(0, 0, 1), ""));
  mission::ScenarioEvent lap;
  lap.at = 6.0;
  lap.kind = mission::ScenarioEvent::Kind::kTrajectory;
  scenario.events.push_back(lap);
  scenario.sim.throw_event.at = 1.0;
  scenario.sim.throw_event.duration = 0.3;
  const std::vector<analysis::ExpectedEvent> events = analysis::expectedEvents(scenario);
  ASSERT_EQ(events.size(), 4u);
  EXPECT_EQ(events[0].label, "throw");
  EXPECT_DOUBLE_EQ(events[0].at, 1.3);  // the hand lets go
  EXPECT_EQ(events[1].label, "goto at 2.0 s");
  EXPECT_EQ(events[2].label, "goto at 5.0 s");
  EXPECT_EQ(events[3].label, "trajectory 1");
}

}  // namespace
}  // namespace sdlqr
