// The view keeps only the newest message per channel and caps what it sends a client: at most 60
// frames a second, none while the connection is backlogged; memory bounded whatever comes in.

#include <gtest/gtest.h>

#include <cstring>

#include "allocation_counter.hpp"
#include "sdlqr/heartbeat_t.hpp"
#include "sdlqr/view/client_pacer.hpp"
#include "sdlqr/view/latest_store.hpp"

namespace sdlqr::view {
namespace {

TEST(LatestStore, KeepsOnlyTheNewestMessageOfEachChannel) {
  LatestStore store;
  for (int i = 0; i < 1000; ++i) store.put("IMU", "", i, &i, sizeof i);
  store.put("SIM_TRUTH", "", 5, "t", 1);
  std::vector<StoredMessage> changed;
  const uint64_t version = store.changedSince(0, &changed);
  ASSERT_EQ(changed.size(), 2u);
  EXPECT_EQ(changed[0].channel, "IMU");
  EXPECT_EQ(changed[0].receive_utime, 999);
  int newest = 0;
  std::memcpy(&newest, changed[0].bytes.data(), sizeof newest);
  EXPECT_EQ(newest, 999);
  EXPECT_EQ(store.stats().slots, 2u);
  // Nothing since; then only what changed.
  EXPECT_EQ(store.changedSince(version, &changed), version);
  EXPECT_TRUE(changed.empty());
  store.put("SIM_TRUTH", "", 6, "u", 1);
  store.changedSince(version, &changed);
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0].channel, "SIM_TRUTH");
}

TEST(LatestStore, RefusesChannelsAndSizesBeyondItsBounds) {
  LatestStore store(2, 8);
  EXPECT_TRUE(store.put("A", "", 0, "12345678", 8));
  EXPECT_FALSE(store.put("A", "", 0, "123456789", 9));
  EXPECT_TRUE(store.put("B", "", 0, "x", 1));
  EXPECT_FALSE(store.put("C", "", 0, "x", 1));  // a third channel
  EXPECT_TRUE(store.put("A", "", 1, "y", 1));
  const StoreStats s = store.stats();
  EXPECT_EQ(s.refused_size, 1u);
  EXPECT_EQ(s.refused_slots, 1u);
  EXPECT_EQ(s.slots, 2u);
  store.clear();
  EXPECT_TRUE(store.put("C", "", 2, "z", 1));  // a cleared store has room again
  std::vector<StoredMessage> changed;
  store.changedSince(0, &changed);
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0].channel, "C");
}

TEST(LatestStore, EachProcessOfAHeartbeatChannelKeepsItsNewest) {
  heartbeat_t beat{};
  beat.process = "sdlqr-gains";
  std::string gains(static_cast<std::size_t>(beat.getEncodedSize()), '\0');
  beat.encode(gains.data(), 0, static_cast<int>(gains.size()));
  beat.process = "sdlqr-sim";
  std::string sim(static_cast<std::size_t>(beat.getEncodedSize()), '\0');
  beat.encode(sim.data(), 0, static_cast<int>(sim.size()));
  EXPECT_EQ(sourceOf("QUAD1/HEARTBEAT", gains.data(), gains.size()), "sdlqr-gains");
  EXPECT_EQ(sourceOf("QUAD1/HEARTBEAT", gains.data(), 3), "");  // not one whole heartbeat
  EXPECT_EQ(sourceOf("QUAD1/IMU", gains.data(), gains.size()), "");
  LatestStore store;
  // Both beat within one frame: neither hides the other.
  store.put("QUAD1/HEARTBEAT", sourceOf("QUAD1/HEARTBEAT", gains.data(), gains.size()), 1, gains.data(), gains.size());
  store.put("QUAD1/HEARTBEAT", sourceOf("QUAD1/HEARTBEAT", sim.data(), sim.size()), 2, sim.data(), sim.size());
  std::vector<StoredMessage> changed;
  store.changedSince(0, &changed);
  ASSERT_EQ(changed.size(), 2u);
  EXPECT_EQ(changed[0].source, "sdlqr-gains");
  EXPECT_EQ(changed[1].source, "sdlqr-sim");
}

TEST(LatestStore, ReplacingAMessageOfTheSameSizeDoesNotAllocate) {
  LatestStore store;
  const std::string channel = "QUAD1/IMU";
  char bytes[89] = {};
  store.put(channel, "", 0, bytes, sizeof bytes);
  const testing::AllocationCounter allocations;
  for (int i = 0; i < 1000; ++i) store.put(channel, "", i, bytes, sizeof bytes);
  EXPECT_EQ(allocations.count(), 0);
}

TEST(ClientPacer, SendsAtMostSixtyFramesASecondHoweverOftenItTicks) {
  ClientPacer pacer;
  for (int ms = 0; ms < 10'000; ++ms) {
    if (pacer.onTick(ms * 1e-3, 0) == ClientPacer::Decision::kSend) pacer.sent(100);
  }
  EXPECT_LE(pacer.counters().frames_sent, 601u);
  EXPECT_GE(pacer.counters().frames_sent, 590u);
}

TEST(ClientPacer, AJitteryTimerAtSixtyHertzKeepsItsFrames) {
  ClientPacer pacer;
  double t = 0.0;
  for (int i = 0; i < 600; ++i) {
    t += (i % 2 ? 0.0160 : 0.0174);  // early and late around 1/60 s
    if (pacer.onTick(t, 0) == ClientPacer::Decision::kSend) pacer.sent(1);
  }
  EXPECT_EQ(pacer.counters().frames_sent, 600u);
  EXPECT_LE(pacer.counters().frames_sent / t, 60.0);
}

TEST(ClientPacer, ABackloggedClientLosesFramesNotTheServersMemory) {
  ClientPacer pacer({60.0, 1000});
  int sent = 0;
  for (int i = 0; i < 120; ++i) {
    const std::size_t buffered = i < 60 ? 5000 : 0;  // stopped reading for a second, then drained
    if (pacer.onTick(i / 60.0, buffered) == ClientPacer::Decision::kSend) ++sent;
  }
  EXPECT_EQ(pacer.counters().frames_skipped, 60u);
  EXPECT_EQ(sent, 60);
  EXPECT_EQ(pacer.counters().max_buffered_bytes, 5000u);
}

}  // namespace
}  // namespace sdlqr::view
