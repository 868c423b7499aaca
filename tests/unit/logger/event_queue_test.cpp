// The hand-over queue never blocks the producer: it drops and counts when full; its memory
// stays what it was at construction however many large messages pass through it.

#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "sdlqr/logger/event_queue.hpp"

namespace sdlqr::logger {
namespace {

using std::chrono::milliseconds;

TEST(EventQueue, FifoWithOverflowCounted) {
  EventQueue queue(3, 1 << 20);
  const uint8_t payload[4] = {1, 2, 3, 4};
  for (int i = 0; i < 5; ++i) {
    const bool accepted = queue.push("CH" + std::to_string(i), payload, static_cast<size_t>(i % 4 + 1), i);
    EXPECT_EQ(accepted, i < 3) << i;
  }
  EventQueueStats stats = queue.stats();
  EXPECT_EQ(stats.pushed, 3);
  EXPECT_EQ(stats.dropped, 2);
  EXPECT_EQ(stats.max_depth, 3);
  QueuedEvent event;
  for (int i = 0; i < 3; ++i) {
    ASSERT_TRUE(queue.pop(&event, milliseconds(0)));
    EXPECT_EQ(event.channel, "CH" + std::to_string(i));
    EXPECT_EQ(event.data.size(), static_cast<size_t>(i + 1));
    EXPECT_EQ(event.receive_utime, i);
  }
  EXPECT_FALSE(queue.pop(&event, milliseconds(1)));
  EXPECT_TRUE(queue.push("AGAIN", payload, 4, 9));  // slots are reused after a pop
}

TEST(EventQueue, ByteLimitDropsLargeBursts) {
  EventQueue queue(100, 10);
  const std::vector<uint8_t> payload(6, 0);
  EXPECT_TRUE(queue.push("A", payload.data(), 6, 0));
  EXPECT_FALSE(queue.push("B", payload.data(), 6, 0));  // 12 bytes > 10
  EXPECT_TRUE(queue.push("C", payload.data(), 4, 0));
  EXPECT_EQ(queue.stats().dropped, 1);
}

TEST(EventQueue, CloseWakesTheConsumerAndKeepsQueuedEvents) {
  EventQueue queue(4, 1024);
  const uint8_t byte = 7;
  ASSERT_TRUE(queue.push("X", &byte, 1, 1));
  std::atomic<int> popped{0};
  std::thread consumer([&] {
    QueuedEvent event;
    while (!queue.closedAndEmpty()) {
      if (queue.pop(&event, milliseconds(5000))) ++popped;
    }
  });
  std::this_thread::sleep_for(milliseconds(20));
  const auto start = std::chrono::steady_clock::now();
  queue.close();
  consumer.join();
  const double waited_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::cout << "[ figures  ] consumer woke " << waited_ms << " ms after close\n";
  EXPECT_LT(waited_ms, 1000.0);
  EXPECT_EQ(popped.load(), 1);
  EXPECT_FALSE(queue.push("Y", &byte, 1, 2));
}

TEST(EventQueue, LargeMessagesLeaveNoMemoryBehind) {
  EventQueue queue(64, 1 << 20);
  const std::size_t at_start = queue.reservedBytes();
  EXPECT_GE(at_start, 64 * EventQueue::kSlotBytes);
  // A large message now and then among small ones lands in every slot over time (a soak's
  // HEARTBEAT and GAINS): had a slot kept it, the reserve would grow by 64 x 4 KiB.
  const std::vector<uint8_t> small(100, 1), large(4096, 2);
  QueuedEvent event;
  for (int i = 0; i < 64 * 20; ++i) {
    const std::vector<uint8_t>& m = i % 7 == 0 ? large : small;
    ASSERT_TRUE(queue.push("A_CHANNEL_NAME_LONGER_THAN_SSO", m.data(), m.size(), i));
    ASSERT_TRUE(queue.pop(&event, milliseconds(0)));
    EXPECT_EQ(event.data, m);
  }
  for (int i = 0; i < 64; ++i) {  // one wrap of typical messages: every large buffer given back
    ASSERT_TRUE(queue.push("A_CHANNEL_NAME_LONGER_THAN_SSO", small.data(), small.size(), i));
    ASSERT_TRUE(queue.pop(&event, milliseconds(0)));
  }
  EXPECT_EQ(queue.reservedBytes(), at_start);
}

}  // namespace
}  // namespace sdlqr::logger
