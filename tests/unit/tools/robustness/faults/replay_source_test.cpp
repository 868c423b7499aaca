// ReplaySource: on a 1 kHz channel a replay is ready after `age` seconds and stays between one and
// two ages old; the fuzzer's replays depended on a gap in the channel before.

#include <gtest/gtest.h>

#include "sdlqr/faults/replay_source.hpp"

namespace sdlqr::faults {
namespace {

std::vector<uint8_t> stamped(int ms) { return {static_cast<uint8_t>(ms & 0xff), static_cast<uint8_t>(ms >> 8)}; }
int stampOf(const std::vector<uint8_t>& bytes) { return bytes[0] | (bytes[1] << 8); }

TEST(ReplaySource, AFastChannelAlwaysHasAMessageBetweenOneAndTwoAgesOld) {
  ReplaySource source(1.0);
  int ready_from_ms = -1;
  for (int ms = 0; ms <= 5000; ++ms) {
    const double now = ms / 1000.0;
    const std::vector<uint8_t> bytes = stamped(ms);
    source.heard(bytes.data(), static_cast<uint32_t>(bytes.size()), now);
    const std::vector<uint8_t>* replay = source.replayable(now);
    if (replay == nullptr) {
      EXPECT_EQ(ready_from_ms, -1) << "a replay was ready and then gone at " << ms << " ms";
      continue;
    }
    if (ready_from_ms < 0) ready_from_ms = ms;
    const int age_ms = ms - stampOf(*replay);
    EXPECT_GE(age_ms, 1000) << "at " << ms << " ms";
    EXPECT_LE(age_ms, 2000) << "at " << ms << " ms";
  }
  EXPECT_EQ(ready_from_ms, 1000);
}

TEST(ReplaySource, NothingIsReplayedBeforeTheFirstMessageIsOldEnough) {
  ReplaySource source(1.0);
  EXPECT_EQ(source.replayable(5.0), nullptr);
  const std::vector<uint8_t> bytes = stamped(0);
  source.heard(bytes.data(), 2, 5.0);
  EXPECT_EQ(source.replayable(5.5), nullptr);
  ASSERT_NE(source.replayable(6.0), nullptr);
  EXPECT_EQ(*source.replayable(6.0), bytes);
}

}  // namespace
}  // namespace sdlqr::faults
