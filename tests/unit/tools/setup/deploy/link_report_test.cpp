// The link figures of sdlqr-linkcheck on synthetic logs with known answers.

#include <gtest/gtest.h>

#include <algorithm>

#include "sdlqr/deploy/link_report.hpp"

namespace sdlqr::deploy {
namespace {

constexpr int64_t kWall0 = 1'700'000'000'000'000;

// A channel received every `period_us` over [0, end_us) except inside [gap_from, gap_to).
logger::ChannelTimeline timeline(const std::string& name, int64_t period_us, int64_t end_us, int64_t bytes,
                                 int64_t gap_from = -1, int64_t gap_to = -1) {
  logger::ChannelTimeline c;
  c.channel = name;
  int64_t seq = 0;
  for (int64_t t = 0; t < end_us; t += period_us, ++seq) {
    if (t >= gap_from && t < gap_to) continue;
    c.addEvent(kWall0 + t, bytes);
    c.addDecoded(kWall0 + t, t, seq);
  }
  return c;
}

TEST(LinkReport, WireBytesCountEveryHeaderAndFragment) {
  // "IMU": 8 + 4 + 100 = 112 UDP payload, + 8 UDP, one frame + 38.
  EXPECT_EQ(wireBytes("IMU", 100), 112 + 8 + 38);
  // 3000 bytes of GAINS: 3022 bytes of IP payload in three 1480-byte frames.
  EXPECT_EQ(wireBytes("GAINS", 3000), 8 + 6 + 3000 + 8 + 3 * 38);
  // Above one datagram: two LCM fragments, each its own UDP datagram.
  const int64_t big = wireBytes("TRAJECTORY", 100000);
  EXPECT_GT(big, 100000 + 2 * (20 + 8));
  EXPECT_LT(big, 100000 + 200 * 38);
}

TEST(LinkReport, BandwidthPerChannelAndTotalOverTheLogSpan) {
  logger::FlightLog log;
  log.channels.push_back(timeline("IMU", 1000, 2'000'001, 100));     // 1 kHz over 2 s
  log.channels.push_back(timeline("GAINS", 100'000, 2'000'001, 3000));  // 10 Hz
  log.channels.push_back(timeline("COMMAND", 1, 1, 20));                 // one message: no rate
  const std::vector<ChannelBandwidth> rows = channelBandwidth(log);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[0].channel, "IMU");  // the largest on the wire first
  EXPECT_NEAR(rows[0].rate_hz, 1000.0, 1e-9);
  EXPECT_NEAR(rows[0].payload_bytes_per_s, 100 * 1000.0, 1e-6);
  EXPECT_NEAR(rows[0].wire_bytes_per_s, 1000.0 * wireBytes("IMU", 100), 1e-6);
  EXPECT_EQ(rows[1].channel, "GAINS");
  EXPECT_NEAR(rows[1].rate_hz, 10.0, 1e-9);
  EXPECT_EQ(rows[2].channel, "COMMAND");
  EXPECT_EQ(rows[2].rate_hz, 0.0);
  EXPECT_EQ(rows[3].channel, "total");
  EXPECT_EQ(rows[3].messages, rows[0].messages + rows[1].messages + 1);
  EXPECT_NEAR(rows[3].wire_bytes_per_s, rows[0].wire_bytes_per_s + rows[1].wire_bytes_per_s, 1e-6);
}

TEST(LinkReport, CrossHostLatencyPairsByTheMessagesOwnNumbers) {
  logger::FlightLog controller_host, lowlevel_host;
  for (int k = 0; k < 10; ++k) {
    const int64_t t = kWall0 + k * 10'000;
    StateEstimate s;
    s.seq = 100 + k;
    controller_host.state_estimate.messages.push_back(s);
    controller_host.state_estimate.receive_utime.push_back(t);
    RateCommand c;
    c.seq = k;
    c.state_seq = s.seq;
    controller_host.rate_command.messages.push_back(c);
    controller_host.rate_command.receive_utime.push_back(t + 300);  // computed in 300 us
    lowlevel_host.rate_command.messages.push_back(c);
    lowlevel_host.rate_command.receive_utime.push_back(t + 500);    // a 200 us hop
  }
  for (int64_t t = kWall0; t < kWall0 + 110'000; t += 1000) lowlevel_host.motor_command.receive_utime.push_back(t + 900);
  lowlevel_host.motor_command.messages.resize(lowlevel_host.motor_command.receive_utime.size());
  const CrossHostLatency latency = crossHostLatency(controller_host, lowlevel_host);
  EXPECT_EQ(latency.state_to_command_us.count, 10);
  EXPECT_DOUBLE_EQ(latency.state_to_command_us.median, 500.0);
  EXPECT_EQ(latency.command_to_motor_us.count, 10);
  EXPECT_DOUBLE_EQ(latency.command_to_motor_us.median, 600.0);  // sent at +300, next motor tick at +900
}

TEST(LinkReport, LinkGapSeesTheSilenceAndLossElsewhere) {
  const int64_t down = kWall0 + 1'000'000, up = kWall0 + 2'000'000;
  const LinkGap clean = measureLinkGap(timeline("IMU", 1000, 3'000'000, 100, 1'000'000, 2'000'000), down, up);
  EXPECT_EQ(clean.longest_gap_us, 1'001'000);
  EXPECT_EQ(clean.received_inside, 0);
  EXPECT_EQ(clean.missing, 1000);
  EXPECT_EQ(clean.missing_outside, 0);
  // Messages also lost half a second later: counted outside the window.
  logger::ChannelTimeline lossy = timeline("IMU", 1000, 3'000'000, 100, 1'000'000, 2'000'000);
  logger::ChannelTimeline more = timeline("IMU", 1000, 3'000'000, 100, 2'500'000, 2'510'000);
  for (size_t i = 0; i < lossy.seq.size(); ++i) {
    if (std::find(more.seq.begin(), more.seq.end(), lossy.seq[i]) == more.seq.end()) lossy.seq[i] = -1;
  }
  logger::ChannelTimeline both;
  for (size_t i = 0; i < lossy.seq.size(); ++i) {
    if (lossy.seq[i] < 0) continue;
    both.addEvent(lossy.receive_utime[i], 100);
    both.addDecoded(lossy.receive_utime[i], lossy.utime[i], lossy.seq[i]);
  }
  const LinkGap elsewhere = measureLinkGap(both, down, up);
  EXPECT_EQ(elsewhere.missing, 1010);
  EXPECT_EQ(elsewhere.missing_outside, 10);
  // A link that never went down: messages inside the window, no gap.
  const LinkGap none = measureLinkGap(timeline("IMU", 1000, 3'000'000, 100), down, up);
  EXPECT_GT(none.received_inside, 800);
  EXPECT_EQ(none.longest_gap_us, 1000);
  EXPECT_EQ(none.missing, 0);
}

// Lowlevel heartbeats once a second over [0, 10 s) whose failsafe.entries steps to 1 at
// `entered_s` (never when negative); the ground recorder hears none while the link is down.
logger::Series<HeartbeatRecord> lowlevelHeartbeats(double entered_s, int64_t down, int64_t up) {
  logger::Series<HeartbeatRecord> series;
  for (int s = 0; s < 10; ++s) {
    const int64_t received = kWall0 + s * 1'000'000 + 3'000;
    if (received > down && received < up) continue;
    HeartbeatRecord hb;
    hb.process = "sdlqr-lowlevel";
    hb.counters.push_back({"failsafe.entries", entered_s >= 0.0 && s >= entered_s ? 1 : 0});
    series.messages.push_back(hb);
    series.receive_utime.push_back(received);
    HeartbeatRecord other = hb;  // another process's counter of that name is not the lowlevel's
    other.process = "sdlqr-estimator";
    other.counters = {{"failsafe.entries", 7}};
    series.messages.push_back(other);
    series.receive_utime.push_back(received);
  }
  return series;
}

TEST(LinkReport, FailsafeEntriesAreJudgedAroundTheOutage) {
  const int64_t down = kWall0 + 3'500'000, up = kWall0 + 5'500'000;
  const FailsafeEntries none = lowlevelFailsafeEntries(lowlevelHeartbeats(-1, down, up), down, up);
  EXPECT_EQ(none.around_outage, 0);
  EXPECT_EQ(none.whole_flight, 0);
  // Entered while the link was down: seen in the first heartbeat after it came up.
  const FailsafeEntries during = lowlevelFailsafeEntries(lowlevelHeartbeats(4.5, down, up), down, up);
  EXPECT_EQ(during.around_outage, 1);
  // ... or just after (a reaction within the settle time).
  EXPECT_EQ(lowlevelFailsafeEntries(lowlevelHeartbeats(6.0, down, up), down, up).around_outage, 1);
  // Entered 3 s after the link came up: not the outage's, but counted over the flight.
  const FailsafeEntries later = lowlevelFailsafeEntries(lowlevelHeartbeats(8.5, down, up), down, up);
  EXPECT_EQ(later.around_outage, 0);
  EXPECT_EQ(later.whole_flight, 1);
  // Without a lowlevel heartbeat after the outage there is nothing to judge by.
  EXPECT_EQ(lowlevelFailsafeEntries(lowlevelHeartbeats(-1, down, kWall0 + 20'000'000), down, up).around_outage, -1);
}

}  // namespace
}  // namespace sdlqr::deploy
