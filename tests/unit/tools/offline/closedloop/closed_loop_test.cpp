// The flight libraries stepped together without a bus, flying the paper's hover experiment
// (§III-C.1): the same checks as the bus test, deterministic and much faster than real time (the
// speed is printed here and measured in bench/; machine speed does not decide a test).

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/closedloop/closed_loop.hpp"
#include "closedloop_test_flights.hpp"
#include "test_paths.hpp"

namespace sdlqr {
namespace {

using ::sdlqr::test::kSourceDir;

struct Flight : test::AnalyzedFlight {
  double wall_seconds = 0.0;
  double sim_seconds = 0.0;
};

Flight fly(const std::string& scenario_file) {
  const mission::Scenario scenario = mission::Scenario::load(kSourceDir + "/config/scenarios/" + scenario_file);
  const closedloop::StackConfig config = closedloop::StackConfig::load(scenario.vehicle_path);
  closedloop::ClosedLoop loop(config, scenario, test::motorCommandsRecorded());
  const auto start = std::chrono::steady_clock::now();
  loop.run();
  Flight flight;
  flight.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  flight.sim_seconds = static_cast<double>(loop.utime()) * 1e-6;
  flight.log = loop.log();
  flight.report = analysis::analyzeFlight(flight.log, scenario);
  return flight;
}

TEST(ClosedLoop, HoverJumpsPassEveryCriterion) {
  const Flight flight = fly("hover_jumps.yaml");
  analysis::writeSummary(flight.report, std::cout);
  const double speedup = flight.sim_seconds / flight.wall_seconds;
  std::cout << "in-process closed loop: " << flight.sim_seconds << " s simulated in " << flight.wall_seconds
            << " s wall, " << speedup << "x real time\n";
  for (const analysis::Check& check : flight.report.checks) {
    EXPECT_TRUE(check.pass) << check.name << " = " << check.value << " (limit " << check.limit << ")";
  }
  EXPECT_EQ(flight.report.setpoints.size(), 7u);  // take-off hold + six jumps
  EXPECT_EQ(flight.report.pulls.size(), 1u);
}

TEST(ClosedLoop, SameScenarioAndSeedFlyTheSameFlightBitForBit) {
  const Flight a = fly("hover_jumps.yaml");
  const Flight b = fly("hover_jumps.yaml");
  ASSERT_EQ(a.log.sim_truth.size(), b.log.sim_truth.size());
  ASSERT_GT(a.log.sim_truth.size(), 1000u);
  for (size_t i = 0; i < a.log.sim_truth.size(); ++i) {
    ASSERT_EQ(a.log.sim_truth[i].position, b.log.sim_truth[i].position) << "sample " << i;
    ASSERT_EQ(a.log.sim_truth[i].orientation, b.log.sim_truth[i].orientation) << "sample " << i;
  }
  ASSERT_EQ(a.log.rate_command.size(), b.log.rate_command.size());
  for (size_t i = 0; i < a.log.rate_command.size(); ++i) {
    ASSERT_EQ(a.log.rate_command[i].body_rate, b.log.rate_command[i].body_rate) << "command " << i;
    ASSERT_EQ(a.log.rate_command[i].thrust, b.log.rate_command[i].thrust) << "command " << i;
  }
}

// A batch worker records each flight into the memory of its last one (ClosedLoop::recordInto):
// the flight is the same as into a new log, nothing of the earlier flight stays, and the 1 kHz
// and 250 Hz series were reserved whole (their storage never moved while flying).
TEST(ClosedLoop, AFlightRecordedIntoAnEarlierFlightsMemoryIsTheSameAndNeverReallocates) {
  const mission::Scenario scenario = mission::Scenario::load(kSourceDir + "/config/scenarios/hover_jumps.yaml");
  const closedloop::StackConfig config = closedloop::StackConfig::load(scenario.vehicle_path);
  closedloop::RecordOptions record;
  record.motor_command = true;
  closedloop::ClosedLoop first(config, scenario, record);
  const SimTruth* truth_storage = first.log().sim_truth.messages.data();
  const StateEstimate* estimate_storage = first.log().state_estimate.messages.data();
  const MotorCommand* motor_storage = first.log().motor_command.messages.data();
  first.run();
  EXPECT_EQ(first.log().sim_truth.messages.data(), truth_storage);
  EXPECT_EQ(first.log().state_estimate.messages.data(), estimate_storage);
  EXPECT_EQ(first.log().motor_command.messages.data(), motor_storage);
  const logger::FlightLog fresh = first.log();

  closedloop::ClosedLoop second(config, scenario, record);
  second.recordInto(first.takeLog());
  EXPECT_TRUE(first.log().sim_truth.empty());
  EXPECT_TRUE(second.log().sim_truth.empty());
  EXPECT_EQ(second.log().sim_truth.messages.data(), truth_storage);  // the first flight's memory
  second.run();
  const logger::FlightLog& reused = second.log();
  EXPECT_EQ(reused.sim_truth.messages.data(), truth_storage);
  ASSERT_EQ(reused.sim_truth.size(), fresh.sim_truth.size());
  for (size_t i = 0; i < fresh.sim_truth.size(); ++i) {
    ASSERT_EQ(reused.sim_truth[i].position, fresh.sim_truth[i].position) << "sample " << i;
  }
  EXPECT_EQ(reused.state_estimate.size(), fresh.state_estimate.size());
  EXPECT_EQ(reused.motor_command.size(), fresh.motor_command.size());
  EXPECT_EQ(reused.rate_command.size(), fresh.rate_command.size());
  EXPECT_EQ(reused.command.size(), fresh.command.size());
  EXPECT_EQ(reused.gains.size(), fresh.gains.size());
}

// sdlqr-mission re-sends its current command once a second with the same seq (for a restarted
// controller): the analysis sees one setpoint per command, not one per re-send.
TEST(ClosedLoop, ReSentCommandsInTheLogDoNotAddSetpoints) {
  const Flight flight = fly("hover_jumps.yaml");
  logger::FlightLog log = flight.log;
  const std::size_t commands = log.command.size();
  ASSERT_GE(commands, 7u);
  for (std::size_t i = 0; i < commands; ++i) {
    Command resent = log.command.messages[i];
    resent.utime += 1'000'000;
    log.command.messages.push_back(resent);
    log.command.receive_utime.push_back(log.command.receive_utime.empty() ? 0 : log.command.receive_utime[i]);
  }
  std::stable_sort(log.command.messages.begin(), log.command.messages.end(),
                   [](const Command& a, const Command& b) { return a.utime < b.utime; });
  const mission::Scenario scenario = mission::Scenario::load(kSourceDir + "/config/scenarios/hover_jumps.yaml");
  const analysis::FlightReport report = analysis::analyzeFlight(log, scenario);
  EXPECT_EQ(report.setpoints.size(), flight.report.setpoints.size());
  EXPECT_EQ(report.checks.size(), flight.report.checks.size());
  for (const analysis::Check& check : report.checks) EXPECT_TRUE(check.pass) << check.name;
}

}  // namespace
}  // namespace sdlqr
