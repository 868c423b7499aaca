// A log played into the store as the bus would have delivered it: in receive-time order, paced by
// wall time and speed; pause, seek (the newest of each channel at the playhead), the end.

#include <gtest/gtest.h>

#include <cstring>

#include "sdlqr/view/log_playback.hpp"

namespace sdlqr::view {
namespace {

// Channel A every 10 ms, B every 100 ms, from t0 for 1 s; added out of order.
LogPlayback sample() {
  LogPlayback p;
  constexpr int64_t t0 = 1'000'000'000;
  for (int i = 100; i >= 0; --i) p.add("A", t0 + 10'000 * i, &i, sizeof i);
  for (int i = 0; i <= 10; ++i) p.add("B", t0 + 100'000 * i, &i, sizeof i);
  p.finishLoading();
  return p;
}

int newest(const LatestStore& store, const std::string& channel) {
  std::vector<StoredMessage> changed;
  store.changedSince(0, &changed);
  for (const StoredMessage& m : changed) {
    if (m.channel != channel) continue;
    int value = 0;
    std::memcpy(&value, m.bytes.data(), sizeof value);
    return value;
  }
  return -1;
}

TEST(LogPlayback, PlaysInReceiveOrderAtItsSpeed) {
  LogPlayback p = sample();
  LatestStore store;
  EXPECT_DOUBLE_EQ(p.durationSeconds(), 1.0);
  p.advance(0.25, store);
  EXPECT_EQ(newest(store, "A"), 25);
  EXPECT_EQ(newest(store, "B"), 2);
  ASSERT_TRUE(p.setSpeed(2.0));
  p.advance(0.1, store);  // 0.2 s of log
  EXPECT_EQ(newest(store, "A"), 45);
  EXPECT_FALSE(p.setSpeed(0.0));
  EXPECT_FALSE(p.setSpeed(100.0));
}

TEST(LogPlayback, PausedItHoldsAndAtTheEndItStops) {
  LogPlayback p = sample();
  LatestStore store;
  p.pause();
  p.advance(0.5, store);
  EXPECT_EQ(newest(store, "A"), -1);
  p.play();
  p.advance(5.0, store);
  EXPECT_EQ(newest(store, "A"), 100);
  EXPECT_FALSE(p.playing());
  EXPECT_DOUBLE_EQ(p.positionSeconds(), 1.0);
}

TEST(LogPlayback, SeekShowsTheNewestOfEachChannelAtThePlayhead) {
  LogPlayback p = sample();
  LatestStore store;
  p.advance(0.9, store);
  p.seek(0.35, store);  // backwards
  EXPECT_EQ(newest(store, "A"), 35);
  EXPECT_EQ(newest(store, "B"), 3);
  EXPECT_DOUBLE_EQ(p.positionSeconds(), 0.35);
  EXPECT_EQ(p.state("f.lcmlog")["seek_count"], 1);
  p.advance(0.05, store);
  EXPECT_EQ(newest(store, "A"), 40);
  p.seek(-3.0, store);  // clamped to the start
  EXPECT_EQ(newest(store, "A"), 0);
  EXPECT_EQ(newest(store, "B"), 0);
}

}  // namespace
}  // namespace sdlqr::view
