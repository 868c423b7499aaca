// The one rejection vocabulary and counter registry of every process (common/health).

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "sdlqr/health/process_health.hpp"

namespace sdlqr {
namespace {

TEST(ProcessHealth, EveryReasonAndStreamHasADistinctName) {
  std::set<std::string> reasons, streams;
  for (int r = 1; r < kRejectReasonCount; ++r) {
    const auto reason = static_cast<RejectReason>(r);
    EXPECT_EQ(std::string(counterName(reason)), std::string("reject.") + reasonName(reason));
    reasons.insert(reasonName(reason));
  }
  EXPECT_EQ(reasons.size(), static_cast<size_t>(kRejectReasonCount - 1));
  EXPECT_EQ(reasons.count("unknown"), 0u);
  for (int s = 0; s < kStreamCount; ++s) streams.insert(streamName(static_cast<Stream>(s)));
  EXPECT_EQ(streams.size(), static_cast<size_t>(kStreamCount));
  EXPECT_EQ(streamOfChannel("STATE_EST"), Stream::kStateEstimate);
  EXPECT_EQ(streamOfChannel("MOTOR_CMD"), Stream::kMotorCommand);
  EXPECT_EQ(streamOfChannel("NOT_A_CHANNEL"), Stream::kOther);
}

TEST(ProcessHealth, RejectionsCountPerStreamAndInTotal) {
  ProcessHealth health;
  EXPECT_FALSE(health.reject(Stream::kGains, RejectReason::kNone));
  EXPECT_TRUE(health.reject(Stream::kGains, RejectReason::kUnstable));
  EXPECT_TRUE(health.reject(Stream::kStateEstimate, RejectReason::kTimeFuture));
  EXPECT_TRUE(health.reject(Stream::kGains, RejectReason::kUnstable));
  EXPECT_EQ(health.rejected(), 3);
  EXPECT_EQ(health.rejections(Stream::kGains, RejectReason::kUnstable), 2);
  EXPECT_EQ(health.rejections(RejectReason::kUnstable), 2);
  EXPECT_EQ(health.counter("reject.unstable"), 2);
  EXPECT_EQ(health.counter("reject.gains.unstable"), 2);
  EXPECT_EQ(health.counter("reject.state_est.time_future"), 1);
  EXPECT_EQ(health.counter("reject.gains.time_future"), 0);
  EXPECT_EQ(health.counter("no.such.counter"), 0);
}

TEST(ProcessHealth, HeartbeatListsEveryTotalTheNonZeroStreamsAndTheNamedCounters) {
  ProcessHealth health;
  const Counters::Id ticks = health.counters().add("controller.ticks");
  EXPECT_EQ(health.counters().add("controller.ticks"), ticks);  // registered once
  health.counters().increment(ticks, 7);
  health.reject(Stream::kParams, RejectReason::kNonFinite);
  std::vector<std::string> names;
  std::vector<int64_t> values;
  health.exportCounters(names, values);
  ASSERT_EQ(names.size(), values.size());
  // kRejectReasonCount - 1 totals, one stream counter, one named counter.
  ASSERT_EQ(names.size(), static_cast<size_t>(kRejectReasonCount - 1 + 2));
  auto value = [&](const std::string& name) {
    for (size_t i = 0; i < names.size(); ++i) {
      if (names[i] == name) return values[i];
    }
    return int64_t{-1};
  };
  EXPECT_EQ(value("reject.nonfinite"), 1);
  EXPECT_EQ(value("reject.params.nonfinite"), 1);
  EXPECT_EQ(value("reject.decode"), 0);
  EXPECT_EQ(value("reject.gains.unstable"), -1);  // zero per-stream counters are left out
  EXPECT_EQ(value("controller.ticks"), 7);
}

}  // namespace
}  // namespace sdlqr
