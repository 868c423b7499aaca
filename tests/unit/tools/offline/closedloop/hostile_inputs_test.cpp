// The hostile inputs of tests/support/hostile_inputs.hpp injected into the in-process loop
// mid-hover: each counted once, by the same cores and counters as on the bus
// (tests/integration/cores) and in the replay (tests/unit/tools/examine/replay).

#include <gtest/gtest.h>

#include <iostream>

#include "hostile_inputs.hpp"
#include "sdlqr/closedloop/closed_loop.hpp"

namespace sdlqr {
namespace {

const std::string kScenario = std::string(SDLQR_SOURCE_DIR) + "/tests/integration/replay/hover_short.yaml";
constexpr int64_t kInjectAt = 5'000'000;  // [us] hovering at 1 m

const ProcessHealth* healthOf(const closedloop::ClosedLoop& loop, const std::string& process) {
  if (process == "sdlqr-controller") return &loop.controller().health();
  if (process == "sdlqr-gains") return &loop.gains().health();
  if (process == "sdlqr-estimator") return &loop.estimator().health();
  if (process == "sdlqr-lowlevel") return &loop.lowlevel().health();
  if (process == "sdlqr-sim") return &loop.sim().health();
  return nullptr;
}

testing::HeardMessages lastHeard(const logger::FlightLog& log) {
  return {log.state_estimate.messages.back(), log.gains.messages.back(), log.command.messages.back(),
          log.imu.messages.back(),           log.reference.messages.back(), log.rate_command.messages.back(),
          log.motor_command.messages.back()};
}

// Flies hover_short, injecting the hostile set at kInjectAt; returns what the cores counted.
std::vector<std::string> flyWithHostileInputs(const closedloop::StackConfig& config, bool inject) {
  const mission::Scenario scenario = mission::Scenario::load(kScenario);
  closedloop::RecordOptions record;
  record.imu = true;
  record.motor_command = true;
  closedloop::ClosedLoop loop(config, scenario, record);
  while (loop.utime() < kInjectAt && loop.step()) {
  }
  if (inject) {
    const testing::HostileInputs h = testing::makeHostileInputs(lastHeard(loop.log()));
    loop.inject(h.far_future_estimate);
    loop.inject(h.destabilizing_gains);
    loop.inject(h.replayed_command);
    loop.inject(h.nan_params);
    loop.inject(h.nan_imu);
    loop.inject(h.future_rate_command);
    loop.inject(h.nan_motor_command);
    loop.inject(h.nan_reference);
  }
  loop.run();
  EXPECT_FALSE(loop.sim().simulator().crashed());
  return testing::rejectionMismatches(
      [&](const std::string& process, const std::string& counter) {
        const ProcessHealth* health = healthOf(loop, process);
        return health ? health->counter(counter) : int64_t{-1};
      },
      testing::Path::kClosedLoop);
}

TEST(HostileInputs, EachIsRejectedOnceInTheClosedLoop) {
  const closedloop::StackConfig config = closedloop::StackConfig::load(SDLQR_SOURCE_DIR "/config/quad255.yaml");
  const std::vector<std::string> mismatches = flyWithHostileInputs(config, true);
  for (const std::string& m : mismatches) std::cout << "  " << m << "\n";
  EXPECT_TRUE(mismatches.empty());
}

// Negative: the check fails on a flight without the hostile inputs (every row counted 0) ...
TEST(HostileInputs, TheCheckFailsWithoutTheInputs) {
  const closedloop::StackConfig config = closedloop::StackConfig::load(SDLQR_SOURCE_DIR "/config/quad255.yaml");
  std::size_t rows = 0;
  for (const testing::ExpectedRejection& row : testing::expectedRejections()) rows += row.on(testing::Path::kClosedLoop);
  EXPECT_EQ(flyWithHostileInputs(config, false).size(), rows);
}

// ... and on the one row whose gate is disabled: a ClockGate that believes one message (no
// confirmation needed) lets the far-future STATE_EST move the clock.
TEST(HostileInputs, TheCheckFailsWhenTheClockGateIsDisabled) {
  closedloop::StackConfig config = closedloop::StackConfig::load(SDLQR_SOURCE_DIR "/config/quad255.yaml");
  config.faults.state_jump_confirmations = 1;
  const std::vector<std::string> mismatches = flyWithHostileInputs(config, true);
  for (const std::string& m : mismatches) std::cout << "  " << m << "\n";
  ASSERT_FALSE(mismatches.empty());
  EXPECT_NE(mismatches.front().find("reject.state_est.time_future = 0"), std::string::npos) << mismatches.front();
}

}  // namespace
}  // namespace sdlqr
