// Metrics on synthetic timelines whose figures are known by construction.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "sdlqr/logger/json_document.hpp"
#include "sdlqr/logger/metrics.hpp"
#include "sdlqr/logger/statistics.hpp"

namespace sdlqr::logger {
namespace {

TEST(Statistics, PercentilesInterpolateLikeNumpy) {
  std::vector<double> values;
  for (int i = 100; i >= 1; --i) values.push_back(i);  // unsorted on purpose
  const Distribution d = describe(values);
  EXPECT_EQ(d.count, 100);
  EXPECT_DOUBLE_EQ(d.mean, 50.5);
  EXPECT_DOUBLE_EQ(d.median, 50.5);
  EXPECT_DOUBLE_EQ(d.p99, 99.01);  // rank 0.99 * 99 = 98.01 -> 99 + 0.01 * (100 - 99)
  EXPECT_EQ(d.min, 1.0);
  EXPECT_EQ(d.max, 100.0);
  const Distribution single = describe({4.0});
  EXPECT_EQ(single.median, 4.0);
  EXPECT_EQ(single.p99, 4.0);
  EXPECT_TRUE(std::isnan(describe({}).mean));
}

ChannelTimeline timeline(const std::string& channel, const std::string& type) {
  ChannelTimeline t;
  t.channel = channel;
  t.lcm_type = type;
  return t;
}

TEST(Metrics, ChannelRatesGapsAndSequenceLosses) {
  // 1 kHz simulated IMU received 2 ms late, one 5-message hole (seq 10..14), then a restart.
  ChannelTimeline imu = timeline("QUAD1/IMU", "imu_t");
  const int64_t receive0 = 1'700'000'000'000'000;
  int64_t seq = 0;
  for (int i = 0; i < 100; ++i, ++seq) {
    if (seq == 10) seq = 15;
    const int64_t utime = 1000 * seq;
    imu.addEvent(receive0 + 2000 + utime, 64);
    imu.addDecoded(receive0 + 2000 + utime, utime, seq);
  }
  imu.addEvent(receive0 + 500'000, 64);
  imu.addDecoded(receive0 + 500'000, 50'000, 0);  // publisher restarted: seq and utime go back

  PacingOrigin origin;
  origin.valid = true;
  origin.channel = "QUAD1/IMU";
  origin.receive_utime = receive0 + 2000;
  origin.utime = 0;
  const ChannelMetrics m = computeChannelMetrics(imu, receive0, origin);
  EXPECT_EQ(m.events, 101);
  EXPECT_EQ(m.bytes, 101 * 64);
  EXPECT_EQ(m.decoded, 101);
  EXPECT_EQ(m.seq_lost, 5);
  EXPECT_EQ(m.seq_restarts, 1);
  EXPECT_EQ(m.seq_repeats, 0);
  EXPECT_EQ(m.utime_not_increasing, 1);
  EXPECT_DOUBLE_EQ(m.first_receive_s, 0.002);
  EXPECT_DOUBLE_EQ(m.receive_interval_ms.median, 1.0);
  EXPECT_DOUBLE_EQ(m.sim_interval_ms.max, 6.0);  // the hole: seq 9 -> 15
  EXPECT_DOUBLE_EQ(m.sim_interval_ms.min, 50.0 - 104.0);  // the restart jumps back
  // 100 paced messages: lag 0; the restarted one: received 0.498 s after the origin,
  // simulated at 0.050 s -> lag 448 ms.
  EXPECT_DOUBLE_EQ(m.pacing_lag_ms.median, 0.0);
  EXPECT_DOUBLE_EQ(m.pacing_lag_ms.max, 448.0);
  EXPECT_EQ(m.first_utime, 0);
  EXPECT_EQ(m.last_utime, 50'000);
}

TEST(Metrics, GainsSolveTimeAndStatus) {
  std::vector<GainSet> gains(100);
  for (int i = 0; i < 100; ++i) {
    gains[static_cast<size_t>(i)].solve_us = i + 1;
    gains[static_cast<size_t>(i)].iterations = 12 + i % 3;
  }
  gains[3].status = SolveStatus::kNotConverged;
  gains[4].method = GainsMethod::kIterative;
  const GainsMetrics m = computeGainsMetrics(gains);
  EXPECT_EQ(m.count, 100);
  EXPECT_DOUBLE_EQ(m.solve_us.mean, 50.5);
  EXPECT_DOUBLE_EQ(m.solve_us.median, 50.5);
  EXPECT_DOUBLE_EQ(m.solve_us.p99, 99.01);
  EXPECT_EQ(m.solve_us.max, 100.0);
  EXPECT_EQ(m.iterations.min, 12.0);
  EXPECT_EQ(m.iterations.max, 14.0);
  EXPECT_EQ(m.status.at("ok"), 99);
  EXPECT_EQ(m.status.at("not_converged"), 1);
  EXPECT_EQ(m.method.at("iterative"), 1);
}

TEST(Metrics, RateCommandJitterInSimulationTime) {
  // Periods 10, 10, 12, 8, 10 ms, then a repeated utime.
  const std::vector<int64_t> utimes = {0, 10'000, 20'000, 32'000, 40'000, 50'000, 50'000};
  std::vector<RateCommand> commands(utimes.size());
  for (size_t i = 0; i < utimes.size(); ++i) commands[i].utime = utimes[i];
  commands[2].saturated = 3;
  commands[5].gains_status = GainsFreshness::kStale;
  const RateCommandMetrics m = computeRateCommandMetrics(commands, 0.01);
  EXPECT_EQ(m.count, 7);
  EXPECT_EQ(m.period_ms.count, 5);
  EXPECT_DOUBLE_EQ(m.period_ms.mean, 10.0);
  EXPECT_DOUBLE_EQ(m.jitter_ms.median, 0.0);
  EXPECT_DOUBLE_EQ(m.jitter_ms.max, 2.0);
  EXPECT_DOUBLE_EQ(m.jitter_ms.p99, 2.0);
  EXPECT_EQ(m.utime_not_increasing, 1);
  EXPECT_EQ(m.rate_saturated, 1);
  EXPECT_EQ(m.thrust_saturated, 1);
  EXPECT_EQ(m.gains_status.at("fresh"), 6);
  EXPECT_EQ(m.gains_status.at("stale"), 1);
}

TEST(Metrics, LastHeartbeatPerProcessAndRestarts) {
  HeartbeatSeries series;
  auto add = [&](const std::string& process, int32_t pid, int8_t state, int64_t receive, int64_t seq) {
    HeartbeatRecord h;
    h.process = process;
    h.pid = pid;
    h.seq = seq;
    h.state = state;
    h.errors = receive;
    h.counters = {{"reject.nan", 3}};
    series.records.push_back(h);
    series.receive_utime.push_back(receive);
  };
  add("sdlqr-gains", 10, 1, 1'000'000, 0);
  add("sdlqr-controller", 11, 1, 1'100'000, 0);
  add("sdlqr-gains", 10, 1, 2'000'000, 3);  // heartbeats 1 and 2 lost
  add("sdlqr-gains", 12, 0, 5'000'000, 0);  // restarted after a 3 s silence: seq starts over
  const std::vector<ProcessHeartbeatMetrics> m = computeHeartbeatMetrics(series, 0);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].process, "sdlqr-controller");
  EXPECT_EQ(m[1].process, "sdlqr-gains");
  EXPECT_EQ(m[1].heartbeats, 3);
  EXPECT_EQ(m[1].distinct_pids, 2);
  EXPECT_EQ(m[1].seq_lost, 2);
  EXPECT_EQ(m[0].seq_lost, 0);

  // On the shared channel itself, seq and clocks of different processes are not mixed.
  ChannelTimeline channel = timeline("HEARTBEAT", "heartbeat_t");
  for (size_t i = 0; i < series.records.size(); ++i) {
    channel.addEvent(series.receive_utime[i], 100);
    channel.addDecoded(series.receive_utime[i], series.records[i].utime, series.records[i].seq);
  }
  PacingOrigin origin;
  origin.valid = true;
  const ChannelMetrics hb = computeChannelMetrics(channel, 0, origin);
  EXPECT_TRUE(hb.several_publishers);
  EXPECT_EQ(hb.seq_restarts, 0);
  EXPECT_FALSE(hb.has_pacing);
  EXPECT_DOUBLE_EQ(hb.receive_interval_ms.max, 3000.0);
  EXPECT_DOUBLE_EQ(m[1].max_interval_s, 3.0);
  EXPECT_EQ(m[1].last.pid, 12);
  EXPECT_EQ(m[1].last.errors, 5'000'000);
  EXPECT_EQ(processStateName(m[1].last.state), "STARTING");
  EXPECT_EQ(processStateName(9), "UNKNOWN(9)");
}

TEST(Metrics, JsonIsValidWithStableOrder) {
  MetricsInput input;
  input.log.path = "a \"quoted\" path.lcmlog";
  input.log.events = 3;
  ChannelTimeline b = timeline("B", "imu_t");
  b.addEvent(10, 8);
  b.addDecoded(10, 5, 0);
  ChannelTimeline a = timeline("A/IMU", "imu_t");
  a.addEvent(20, 8);
  ChannelTimeline unknown = timeline("OTHER", "");
  unknown.addEvent(30, 1);
  input.channels = {b, a, unknown};
  input.gains["A/GAINS"] = {GainSet{}};
  const LogMetrics metrics = computeLogMetrics(input, MetricsOptions{});
  std::ostringstream out;
  writeMetricsJson(out, metrics);
  JsonDocument json;
  std::string error;
  ASSERT_TRUE(parseJson(out.str(), &json, &error)) << error << "\n" << out.str();
  std::vector<std::string> top;
  for (const auto& member : json.items()) top.push_back(member.key());
  EXPECT_EQ(top, (std::vector<std::string>{"log", "pacing", "channels", "gains", "rate_cmd", "heartbeat"}));
  ASSERT_TRUE(json.contains("channels"));
  const JsonDocument& channels = json["channels"];
  std::vector<std::string> names;
  for (const auto& member : channels.items()) names.push_back(member.key());
  EXPECT_EQ(names, (std::vector<std::string>{"A/IMU", "B", "OTHER"}));
  EXPECT_TRUE(channels["OTHER"]["type"].is_null());
  // One event: no rate -> null, not NaN.
  EXPECT_TRUE(channels["B"]["receive"]["rate_hz"].is_null());
  EXPECT_EQ(json["log"]["path"].get<std::string>(), input.log.path);
  EXPECT_EQ(json["pacing"]["origin_channel"].get<std::string>(), "B");
  // Writing twice gives the same bytes.
  std::ostringstream again;
  writeMetricsJson(again, computeLogMetrics(input, MetricsOptions{}));
  EXPECT_EQ(out.str(), again.str());
}

}  // namespace
}  // namespace sdlqr::logger
