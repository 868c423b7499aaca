// The soak judge on synthetic series: a flat run passes, and each kind of growth — a leak, a
// descriptor leak, CPU creeping up, latency growing, a process vanishing or never sampled, a gap
// in the log — fails it.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "sdlqr/soak/soak_check.hpp"
#include "sdlqr/soak/soak_log.hpp"
#include "test_paths.hpp"

namespace sdlqr::soak {
namespace {

// `minutes` sampled every 2 s: RSS grows by rss_kib_per_s, fds by one every fd_every_s seconds
// (0: never), CPU at 20 % of a core + cpu_growth_per_min per minute.
std::vector<ResourceSample> run(double rss_kib_per_s, double fd_every_s = 0.0, double cpu_growth_per_min = 0.0,
                                double minutes = 10.0) {
  std::vector<ResourceSample> out;
  double cpu = 0.0;
  for (double t = 0.0; t <= 60.0 * minutes; t += 2.0) {
    const double percent = 20.0 + cpu_growth_per_min * t / 60.0;
    cpu += 2.0 * percent / 100.0;
    const int64_t fds = 12 + (fd_every_s > 0.0 ? static_cast<int64_t>(t / fd_every_s) : 0);
    out.push_back({t, "sdlqr-controller", 8000.0 + rss_kib_per_s * t, fds, cpu});
    out.push_back({t, "sdlqr-sim", 9000.0, 11, cpu});
  }
  return out;
}

std::vector<LatencySample> latency(double us_per_min = 0.0, double minutes = 10.0) {
  std::vector<LatencySample> out;
  for (double t = 0.0; t < 60.0 * minutes; t += 0.01) out.push_back({t, 300.0 + us_per_min * t / 60.0});
  return out;
}

bool failed(const SoakReport& r, const std::string& prefix) {
  for (const SoakCheck& c : r.checks) {
    if (!c.pass && c.name.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

TEST(SoakCheck, AFlatRunPasses) {
  const SoakReport r = judgeGrowth(run(0.0), latency(), 0.0, 600.0, GrowthLimits{});
  EXPECT_EQ(r.windows.size(), 10u);
  EXPECT_TRUE(r.passed());
  EXPECT_FALSE(r.checks.empty());
}

TEST(SoakCheck, ALeakOfOneKibPerSecondFailsIn30Minutes) {
  EXPECT_TRUE(judgeGrowth(run(1.0), latency(), 0.0, 600.0, GrowthLimits{}).passed());  // 600 KiB in 10 min
  const SoakReport r = judgeGrowth(run(1.0, 0.0, 0.0, 30.0), latency(0.0, 30.0), 0.0, 1800.0, GrowthLimits{});
  EXPECT_FALSE(r.passed());
  EXPECT_TRUE(failed(r, "rss_kib[sdlqr-controller]"));
  EXPECT_FALSE(failed(r, "rss_kib[sdlqr-sim]"));
}

TEST(SoakCheck, ADescriptorLeakFails) {
  const SoakReport r = judgeGrowth(run(0.0, 120.0), latency(), 0.0, 600.0, GrowthLimits{});
  EXPECT_TRUE(failed(r, "fds[sdlqr-controller]"));
}

TEST(SoakCheck, CpuCreepingUpFails) {
  // 20 % -> 45 % of a core over 10 minutes: above 1.5 x 20 + 5.
  const SoakReport r = judgeGrowth(run(0.0, 0.0, 2.5), latency(), 0.0, 600.0, GrowthLimits{});
  EXPECT_TRUE(failed(r, "cpu_percent[sdlqr-controller]"));
}

TEST(SoakCheck, GrowingLatencyFails) {
  const SoakReport r = judgeGrowth(run(0.0), latency(60.0), 0.0, 600.0, GrowthLimits{});  // 300 -> 870 us
  EXPECT_TRUE(failed(r, "state_to_command_median_us"));
}

TEST(SoakCheck, AProcessThatVanishesFails) {
  std::vector<ResourceSample> samples;
  for (const ResourceSample& s : run(0.0)) {
    if (s.process != "sdlqr-sim" || s.t < 300.0) samples.push_back(s);
  }
  EXPECT_TRUE(failed(judgeGrowth(samples, latency(), 0.0, 600.0, GrowthLimits{}), "sampled[sdlqr-sim]"));
}

// Growth is judged only for processes that were sampled: a process the launcher started that has
// no samples at all (or an empty series) fails, named, instead of leaving its memory unjudged.
TEST(SoakCheck, AStartedProcessWithoutSamplesFails) {
  const std::vector<std::string> started = {"sdlqr-controller", "sdlqr-sim", "sdlqr-logger"};
  const SoakReport r = judgeGrowth(run(0.0), latency(), 0.0, 600.0, GrowthLimits{}, started);
  EXPECT_FALSE(r.passed());
  EXPECT_TRUE(failed(r, "sampled[sdlqr-logger]@window 1"));
  EXPECT_FALSE(failed(r, "sampled[sdlqr-controller]"));
  EXPECT_TRUE(judgeGrowth(run(0.0), latency(), 0.0, 600.0, GrowthLimits{}, {"sdlqr-controller", "sdlqr-sim"}).passed());
  // No sample at all: every started process fails, none passes by being absent.
  const SoakReport empty = judgeGrowth({}, latency(), 0.0, 600.0, GrowthLimits{}, started);
  EXPECT_FALSE(empty.passed());
  for (const std::string& name : started) EXPECT_TRUE(failed(empty, "sampled[" + name + "]")) << name;
}

TEST(SoakCheck, FewerThanTwoWindowsIsAnError) {
  EXPECT_THROW(judgeGrowth(run(0.0), latency(), 0.0, 100.0, GrowthLimits{}), std::invalid_argument);
}

TEST(SoakCheck, ReadsTheRunnersCsvAndNamesABadLine) {
  const std::string path = sdlqr::test::tempPath("soak_samples.csv");
  {
    std::ofstream out(path);
    out << "t,process,rss_kib,fds,cpu_seconds\n1.5,sdlqr-sim,9000,11,0.25\n";
  }
  const auto samples = readSamples(path);
  ASSERT_EQ(samples.size(), 1u);
  EXPECT_EQ(samples[0].process, "sdlqr-sim");
  EXPECT_EQ(samples[0].fds, 11);
  {
    std::ofstream out(path, std::ios::app);
    out << "2.0,sdlqr-sim,lots,11,0.3\n";
  }
  try {
    readSamples(path);
    FAIL() << "a malformed row was accepted";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(":3:"), std::string::npos) << e.what();
  }
  std::remove(path.c_str());
}

logger::FlightLog logWithSeq(std::vector<int64_t> seq) {
  logger::FlightLog log;
  logger::ChannelTimeline c;
  c.channel = "STATE_EST";
  c.seq = std::move(seq);
  c.utime.assign(c.seq.size(), 0);  // decoded, as the reader fills them
  c.receive_utime.assign(c.seq.size(), 0);
  log.channels.push_back(c);
  logger::ChannelTimeline hb;
  hb.channel = "HEARTBEAT";
  hb.lcm_type = "heartbeat_t";
  hb.seq = {0, 7, 1, 9};  // every process's own seq interleaved: never a gap
  log.channels.push_back(hb);
  for (int i = 0; i < 100; ++i) {
    SimTruth s;
    s.utime = i * 1000000;
    s.on_ground = false;
    log.sim_truth.messages.push_back(s);
    log.sim_truth.receive_utime.push_back(1700000000000000 + i * 1000000);
  }
  return log;
}

TEST(SoakLog, AWholeLogPassesAndAGapOrACrashFails) {
  const LogWholeness whole = checkLogWhole(logWithSeq({0, 1, 2, 3}));
  EXPECT_EQ(whole.seq_lost, 0);
  EXPECT_DOUBLE_EQ(whole.airborne_sim_s, 99.0);
  EXPECT_DOUBLE_EQ(whole.airborne_start, 1700000000.0);
  EXPECT_TRUE(whole.passed(90.0));
  EXPECT_FALSE(whole.passed(120.0));  // too short

  const LogWholeness gap = checkLogWhole(logWithSeq({0, 1, 5, 6}));
  EXPECT_EQ(gap.seq_lost, 3);
  EXPECT_EQ(gap.worst_channel, "STATE_EST");
  EXPECT_FALSE(gap.passed(90.0));

  logger::FlightLog crashed = logWithSeq({0, 1});
  crashed.sim_truth.messages[50].crashed = true;
  EXPECT_FALSE(checkLogWhole(crashed).passed(90.0));

  logger::FlightLog torn = logWithSeq({0, 1});
  torn.file.truncated_tail_bytes = 12;
  EXPECT_FALSE(checkLogWhole(torn).passed(90.0));
}

}  // namespace
}  // namespace sdlqr::soak
