// The hostile inputs of tests/support/hostile_inputs.hpp in a recorded flight: the replay feeds
// them to the same cores as the bus and the in-process loop, which count each once, and the
// recomputed outputs stay those of the clean flight.

#include <gtest/gtest.h>

#include <iostream>

#include "flight_fixture.hpp"
#include "hostile_inputs.hpp"

namespace sdlqr::replay {
namespace {

constexpr int64_t kInjectAt = 5'000'000;  // [us] hovering at 1 m

template <class T>
void insertAt(RecordedFlight& f, std::size_t position, InputKind kind, std::vector<T>& series, const T& message) {
  series.push_back(message);
  f.order.insert(f.order.begin() + static_cast<std::ptrdiff_t>(position),
                 LogPosition{kind, static_cast<int32_t>(series.size() - 1)});
}

template <class T>
const T& lastBefore(const std::vector<T>& series, int64_t utime) {
  std::size_t i = 0;
  while (i + 1 < series.size() && series[i + 1].utime <= utime) ++i;
  return series[i];
}

// The clean flight with the hostile set heard at kInjectAt.
RecordedFlight withHostileInputs(const RecordedFlight& clean) {
  RecordedFlight f = clean;
  std::size_t p = 0;
  while (p < f.order.size() && !(f.order[p].kind == InputKind::kImu && f.utimeAt(f.order[p]) >= kInjectAt)) ++p;
  const testing::HeardMessages heard{lastBefore(f.state_estimate, kInjectAt), lastBefore(f.gains, kInjectAt),
                                     lastBefore(f.command, kInjectAt), f.imu[static_cast<std::size_t>(f.order[p - 1].index)],
                                     lastBefore(f.reference, kInjectAt), lastBefore(f.rate_command, kInjectAt),
                                     MotorCommand{}};
  const testing::HostileInputs h = testing::makeHostileInputs(heard);
  insertAt(f, p, InputKind::kImu, f.imu, h.nan_imu);
  insertAt(f, p, InputKind::kParams, f.params, h.nan_params);
  insertAt(f, p, InputKind::kCommand, f.command, h.replayed_command);
  insertAt(f, p, InputKind::kGains, f.gains, h.destabilizing_gains);
  insertAt(f, p, InputKind::kStateEstimate, f.state_estimate, h.far_future_estimate);
  // What the loader keeps of a GAINS the size walk refused (flight_loader.cpp).
  insertAt(f, p, InputKind::kUndecodable, f.undecodable, UndecodableInput{heard.gains.utime, Stream::kGains,
                                                                             RejectReason::kBadSize});
  return f;
}

std::vector<std::string> mismatchesOf(const Recomputation& replay) {
  return testing::rejectionMismatches(
      [&](const std::string& process, const std::string& counter) -> int64_t {
        if (process == "sdlqr-controller") return replay.controller().health().counter(counter);
        if (process == "sdlqr-gains") return replay.gains().health().counter(counter);
        if (process == "sdlqr-estimator") return replay.estimator().health().counter(counter);
        return -1;
      },
      testing::Path::kReplay);
}

const test::ClosedLoopFlight& cleanFlight() {
  static const test::ClosedLoopFlight flight = test::flyClosedLoop();
  return flight;
}

TEST(HostileReplay, EachIsRejectedOnceAndTheOutputsStayTheCleanFlights) {
  const test::ClosedLoopFlight& c = cleanFlight();
  Recomputation clean(test::paramsOf(c.config), c.flight);
  clean.runToEnd();
  const RecordedFlight hostile_flight = withHostileInputs(c.flight);
  Recomputation hostile(test::paramsOf(c.config), hostile_flight);
  hostile.runToEnd();

  const std::vector<std::string> mismatches = mismatchesOf(hostile);
  for (const std::string& m : mismatches) std::cout << "  " << m << "\n";
  EXPECT_TRUE(mismatches.empty());
  EXPECT_EQ(hostile.pairing().foreign_estimates, 1);
  EXPECT_EQ(hostile.pairing().foreign_gains, 1);
  EXPECT_EQ(clean.pairing().rejected, 0);
  const ReplayOutputs& a = clean.outputs();
  const ReplayOutputs& b = hostile.outputs();
  ASSERT_EQ(a.rate_command.size(), b.rate_command.size());
  ASSERT_EQ(a.gains.size(), b.gains.size());
  for (std::size_t i = 0; i < a.rate_command.size(); ++i) {
    ASSERT_EQ(a.rate_command[i].body_rate, b.rate_command[i].body_rate) << "RATE_CMD " << i;
    ASSERT_EQ(a.rate_command[i].thrust, b.rate_command[i].thrust) << "RATE_CMD " << i;
  }
  for (std::size_t i = 0; i < a.gains.size(); ++i) ASSERT_EQ(a.gains[i].K, b.gains[i].K) << "GAINS " << i;
}

// Negative: without the hostile inputs every row is missing; with a ClockGate that needs no
// confirmation the far-future STATE_EST is accepted and its rows fail.
TEST(HostileReplay, TheCheckFailsWithoutTheInputsOrWithTheClockGateDisabled) {
  const test::ClosedLoopFlight& c = cleanFlight();
  Recomputation clean(test::paramsOf(c.config), c.flight);
  clean.runToEnd();
  std::size_t replay_rows = 0;
  for (const testing::ExpectedRejection& row : testing::expectedRejections()) replay_rows += row.on(testing::Path::kReplay);
  EXPECT_EQ(mismatchesOf(clean).size(), replay_rows);

  ReplayParams permissive = test::paramsOf(c.config);
  permissive.faults.state_jump_confirmations = 1;
  const RecordedFlight hostile_flight = withHostileInputs(c.flight);
  Recomputation hostile(permissive, hostile_flight);
  hostile.runToEnd();
  const std::vector<std::string> mismatches = mismatchesOf(hostile);
  for (const std::string& m : mismatches) std::cout << "  " << m << "\n";
  ASSERT_GE(mismatches.size(), 2u);
  EXPECT_NE(mismatches[0].find("sdlqr-controller reject.state_est.time_future = 0"), std::string::npos);
}

}  // namespace
}  // namespace sdlqr::replay
