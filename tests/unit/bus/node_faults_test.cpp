// Node's defences and fault injection over memq:// (no network): the pre-decode size walk
// (truncated, oversized, forged array lengths), fingerprint rejects, and seeded drop/delay.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "allocation_counter.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "bus_test_helpers.hpp"

namespace sdlqr::bus {
namespace {

using test::keyOf;
using test::memq;

int64_t counter(Node& node, const std::string& name) { return node.health().counter(name); }

std::vector<uint8_t> encode(const state_estimate_t& m) {
  std::vector<uint8_t> bytes(static_cast<size_t>(m.getEncodedSize()));
  m.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  return bytes;
}

state_estimate_t plainEstimate(int64_t seq) {
  StateEstimate s;
  s.utime = seq * 4000;
  s.seq = seq;
  s.status = EstimatorStatus::kOk;
  return toLcm(s);
}

void drain(Node& node) {
  while (node.lcm().handleTimeout(0) > 0) {
  }
}

TEST(NodeDefences, TruncatedAndOversizedEncodingsAreSizeRejects) {
  Node node("test", memq());
  int handled = 0;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t&) { ++handled; }, 16);
  std::vector<uint8_t> bytes = encode(plainEstimate(1));
  node.lcm().publish("STATE_EST", bytes.data(), static_cast<unsigned>(bytes.size() - 1));  // truncated
  bytes.push_back(0);
  node.lcm().publish("STATE_EST", bytes.data(), static_cast<unsigned>(bytes.size()));  // one byte too many
  bytes.pop_back();
  node.lcm().publish("STATE_EST", bytes.data(), static_cast<unsigned>(bytes.size()));  // exact
  drain(node);
  EXPECT_EQ(handled, 1);
  EXPECT_EQ(counter(node, "reject.size"), 2);
  EXPECT_EQ(node.rejected(), 2);
}

TEST(NodeDefences, WrongFingerprintOfTheRightSizeIsADecodeReject) {
  Node node("test", memq());
  int handled = 0;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t&) { ++handled; }, 16);
  std::vector<uint8_t> bytes = encode(plainEstimate(1));
  bytes[0] ^= 0xff;
  node.lcm().publish("STATE_EST", bytes.data(), static_cast<unsigned>(bytes.size()));
  drain(node);
  EXPECT_EQ(handled, 0);
  EXPECT_EQ(counter(node, "reject.decode"), 1);
}

TEST(NodeDefences, AForgedSampleCountAllocatesNothing) {
  Node node("test", memq());
  int handled = 0;
  node.subscribe<trajectory_t>(channel::kTrajectory, [&](const trajectory_t&) { ++handled; }, 4);
  trajectory_t trajectory{};
  trajectory.num_samples = 0;
  std::vector<uint8_t> bytes(static_cast<size_t>(trajectory.getEncodedSize()));
  trajectory.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  // num_samples follows the fingerprint, utime, seq, start_utime, tracking and closed.
  constexpr size_t kNumSamplesOffset = 8 + 8 + 8 + 8 + 1 + 1;
  node.lcm().handleTimeout(0);
  const long before = sdlqr::testing::allocationCount();
  const uint32_t forged_counts[] = {0x7fffffffu, 1000000u, 2u, 0xffffffffu};
  for (uint32_t count : forged_counts) {  // 2^31 samples of 15 doubles: 250 GB if decoded blindly
    std::vector<uint8_t> copy = bytes;
    for (int i = 0; i < 4; ++i) copy[kNumSamplesOffset + static_cast<size_t>(i)] = static_cast<uint8_t>(count >> (24 - 8 * i));
    node.lcm().publish("TRAJECTORY", copy.data(), static_cast<unsigned>(copy.size()));
    drain(node);
  }
  const long allocations = sdlqr::testing::allocationCount() - before;
  std::cout << "forged sample counts 4, handled " << handled << ", allocations (memq's copies included) "
            << allocations << "\n";
  EXPECT_EQ(handled, 0);
  EXPECT_EQ(counter(node, "reject.size"), 4);
  EXPECT_LT(allocations, 40);  // memq copies each message into a few small blocks
  // The unforged zero-sample encoding still decodes (the validator, not the walk, refuses it).
  node.lcm().publish("TRAJECTORY", bytes.data(), static_cast<unsigned>(bytes.size()));
  drain(node);
  EXPECT_EQ(handled, 1);
}

TEST(FaultInjection, ParsesTheSpecAndNamesTheBadField) {
  const FaultInjection f = FaultInjection::parse("drop=0.1,delay_ms=0:5,seed=42");
  EXPECT_DOUBLE_EQ(f.drop, 0.1);
  EXPECT_DOUBLE_EQ(f.delay_min_ms, 0.0);
  EXPECT_DOUBLE_EQ(f.delay_max_ms, 5.0);
  EXPECT_EQ(f.seed, 42u);
  EXPECT_TRUE(f.enabled());
  EXPECT_FALSE(FaultInjection::parse("").enabled());
  for (const char* bad : {"drop=1", "drop=-0.1", "drop=x", "delay_ms=5:1", "seed=-1", "jitter=3", "drop"}) {
    try {
      FaultInjection::parse(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("SDLQR_FAULTS"), std::string::npos) << e.what();
    }
  }
}

TEST(FaultInjection, TheEnvironmentTurnsItOn) {
  ::setenv("SDLQR_FAULTS", "drop=0.25,seed=3", 1);
  Node node("test", memq());
  ::unsetenv("SDLQR_FAULTS");
  EXPECT_DOUBLE_EQ(node.faultInjection().drop, 0.25);
  Node clean("test", memq());
  EXPECT_FALSE(clean.faultInjection().enabled());
  ::setenv("SDLQR_FAULTS", "drop=2", 1);
  EXPECT_THROW(Node("test", memq()), std::invalid_argument);
  ::unsetenv("SDLQR_FAULTS");
}

std::vector<int64_t> deliveredSeqs(uint64_t seed, int count) {
  Node node("test", memq());
  FaultInjection faults;
  faults.drop = 0.1;
  faults.seed = seed;
  node.setFaultInjection(faults);
  std::vector<int64_t> seqs;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& m) { seqs.push_back(m.seq); },
                                   64);
  for (int i = 0; i < count; ++i) {
    node.publish(channel::kStateEstimate, plainEstimate(i));
    node.spin(0);
  }
  return seqs;
}

TEST(FaultInjection, DropsTheConfiguredFractionReproduciblyPerSeed) {
  constexpr int kCount = 20000;
  const std::vector<int64_t> a = deliveredSeqs(7, kCount);
  const std::vector<int64_t> b = deliveredSeqs(7, kCount);
  const std::vector<int64_t> c = deliveredSeqs(8, kCount);
  const double dropped = 1.0 - static_cast<double>(a.size()) / kCount;
  const double sigma = std::sqrt(0.1 * 0.9 / kCount);
  std::cout << "dropped " << dropped * 100.0 << " % of " << kCount << " (configured 10 %, 4 sigma = "
            << 4 * sigma * 100.0 << " %)\n";
  EXPECT_NEAR(dropped, 0.1, 4 * sigma);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(FaultInjection, DelaysWithinTheRangeAndKeepsEachChannelInOrder) {
  Node node("test", memq());
  FaultInjection faults;
  faults.delay_min_ms = 2.0;
  faults.delay_max_ms = 5.0;
  faults.seed = 11;
  node.setFaultInjection(faults);
  using Clock = std::chrono::steady_clock;
  std::vector<Clock::time_point> sent;
  std::vector<double> latency_ms;
  std::vector<int64_t> order;
  node.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& m) {
    order.push_back(m.seq);
    latency_ms.push_back(
        std::chrono::duration<double, std::milli>(Clock::now() - sent[static_cast<size_t>(m.seq)]).count());
  }, 64);
  constexpr int kCount = 300;
  for (int i = 0; i < kCount; ++i) {
    sent.push_back(Clock::now());
    node.publish(channel::kStateEstimate, plainEstimate(i));
    node.spin(0);
    const auto next = Clock::now() + std::chrono::milliseconds(1);
    while (Clock::now() < next) node.spin(1);
  }
  const auto end = Clock::now() + std::chrono::milliseconds(50);
  while (Clock::now() < end) node.spin(5);
  ASSERT_EQ(static_cast<int>(order.size()), kCount);
  for (int i = 0; i < kCount; ++i) EXPECT_EQ(order[static_cast<size_t>(i)], i);
  double min = 1e9, max = 0.0, sum = 0.0;
  for (double l : latency_ms) {
    min = std::min(min, l);
    max = std::max(max, l);
    sum += l;
  }
  std::cout << "delay over " << kCount << " messages at 1 kHz: min " << min << " ms, mean " << sum / kCount
            << " ms, max " << max << " ms (configured 2-5 ms)\n";
  EXPECT_GE(min, 2.0);
  EXPECT_GT(sum / kCount, 3.0);  // a uniform 2-5 ms draw has mean 3.5 ms
  EXPECT_EQ(counter(node, "fault.delayed"), kCount);
}

}  // namespace
}  // namespace sdlqr::bus
