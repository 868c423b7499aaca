#include <gtest/gtest.h>

#include "sdlqr/estimator/state_history.hpp"

namespace sdlqr::estimator {
namespace {

void pushAt(StateHistory& history, int64_t utime) {
  HistoryEntry& e = history.pushNewest();
  e.utime = utime;
  e.state.position.x() = static_cast<double>(utime);
}

TEST(StateHistory, KeepsTheNewestEntriesInTimeOrderWhenItWraps) {
  // GIVEN a history of 5 entries
  StateHistory history(5);
  EXPECT_TRUE(history.empty());
  // WHEN 8 states are pushed
  for (int64_t k = 1; k <= 8; ++k) pushAt(history, 4000 * k);
  // THEN the last 5 remain, oldest first, each with its own contents
  ASSERT_EQ(history.size(), 5);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(history.at(i).utime, 4000 * (i + 4));
    EXPECT_EQ(history.at(i).state.position.x(), static_cast<double>(4000 * (i + 4)));
  }
  EXPECT_EQ(history.oldest().utime, 16000);
  EXPECT_EQ(history.newest().utime, 32000);
}

TEST(StateHistory, FindsTheEntryAtOrBeforeATime) {
  StateHistory history(4);
  for (int64_t k = 1; k <= 6; ++k) pushAt(history, 4000 * k);  // holds 12000 .. 24000
  EXPECT_EQ(history.indexAtOrBefore(11999), -1);
  EXPECT_EQ(history.indexAtOrBefore(12000), 0);
  EXPECT_EQ(history.indexAtOrBefore(15999), 0);
  EXPECT_EQ(history.indexAtOrBefore(16000), 1);
  EXPECT_EQ(history.indexAtOrBefore(23999), 2);
  EXPECT_EQ(history.indexAtOrBefore(24000), 3);
  EXPECT_EQ(history.indexAtOrBefore(1'000'000), 3);
  history.clear();
  EXPECT_EQ(history.indexAtOrBefore(24000), -1);
}

TEST(StateHistory, RejectsACapacityTooSmallToRewind) { EXPECT_THROW(StateHistory(1), std::invalid_argument); }

}  // namespace
}  // namespace sdlqr::estimator
