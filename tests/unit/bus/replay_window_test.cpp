// The replay window of a signed bus's subscriber (common/bus replay_window.hpp): per link, only
// newer timestamps; for every link, only timestamps within the window of the receiver's clock.

#include <gtest/gtest.h>

#include "sdlqr/bus/replay_window.hpp"

namespace sdlqr::bus {
namespace {

constexpr uint64_t kNow = 1'000'000'000;  // [10 us]

TEST(ReplayWindow, EachLinkMustMoveForward) {
  ReplayWindow window(1000);
  EXPECT_EQ(window.offer(1, kNow, kNow), RejectReason::kNone);
  EXPECT_EQ(window.offer(1, kNow, kNow), RejectReason::kReplayed);       // the same message again
  EXPECT_EQ(window.offer(1, kNow - 1, kNow), RejectReason::kReplayed);   // an older one
  EXPECT_EQ(window.offer(1, kNow + 1, kNow), RejectReason::kNone);
  EXPECT_EQ(window.offer(2, kNow - 5, kNow), RejectReason::kNone);  // another link has its own sequence
}

TEST(ReplayWindow, TimestampsOutsideTheWindowOfTheReceiversClockAreRefused) {
  ReplayWindow window(1000);
  EXPECT_EQ(window.offer(1, kNow - 1001, kNow), RejectReason::kSignatureWindow);  // too old for a new link
  EXPECT_EQ(window.offer(1, kNow + 1001, kNow), RejectReason::kSignatureWindow);  // from the future
  EXPECT_EQ(window.offer(1, kNow - 1000, kNow), RejectReason::kNone);             // at the edges: in
  EXPECT_EQ(window.offer(2, kNow + 1000, kNow), RejectReason::kNone);
  // A refused timestamp is not remembered: the link's newest is still kNow - 1000.
  EXPECT_EQ(window.offer(1, kNow - 999, kNow), RejectReason::kNone);
}

TEST(ReplayWindow, APastWindowTimestampIsTooOldEvenAfterTheReceiverClockWasBelowIt) {
  ReplayWindow window(1000);
  EXPECT_EQ(window.offer(7, 10, 0), RejectReason::kNone);  // near the epoch: no unsigned wrap-around
  EXPECT_EQ(window.offer(7, 11, 5000), RejectReason::kSignatureWindow);
}

TEST(ReplayWindow, ANewLinkPastCapacityReplacesTheStalestAndKeepsTheOthers) {
  ReplayWindow window(1'000'000);
  for (uint32_t link = 0; link < ReplayWindow::kLinks; ++link) {
    EXPECT_EQ(window.offer(link, kNow + link, kNow), RejectReason::kNone);
  }
  EXPECT_EQ(window.offer(100, kNow + 100, kNow), RejectReason::kNone);  // replaces link 0 (oldest)
  for (uint32_t link = 1; link < ReplayWindow::kLinks; ++link) {
    EXPECT_EQ(window.offer(link, kNow + link, kNow), RejectReason::kReplayed) << "link " << link;
  }
  EXPECT_EQ(window.offer(100, kNow + 100, kNow), RejectReason::kReplayed);
  // Link 0 was forgotten: only the clock window bounds it now (replay_window.hpp).
  EXPECT_EQ(window.offer(0, kNow, kNow), RejectReason::kNone);
}

}  // namespace
}  // namespace sdlqr::bus
