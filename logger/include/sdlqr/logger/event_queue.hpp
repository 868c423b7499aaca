#pragma once
// Bounded hand-over from the LCM handler thread to the log writer thread. The handler only
// copies into a preallocated slot (no allocation once every slot has seen its largest
// message) and never waits for the writer: when the queue is full the event is dropped and
// counted, so a slow disk can never block the bus.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace sdlqr::logger {

struct QueuedEvent {
  std::string channel;
  std::vector<uint8_t> data;
  int64_t receive_utime = 0;  // [us]
};

struct EventQueueStats {
  int64_t pushed = 0;
  int64_t dropped = 0;       // refused because the queue was full (events or bytes)
  int64_t max_depth = 0;     // most events queued at once
  int64_t depth = 0;
};

class EventQueue {
 public:
  // Holds at most `max_events` events and `max_bytes` payload bytes.
  EventQueue(std::size_t max_events, std::size_t max_bytes);

  // Producer side. False (and counted as dropped) when full or closed.
  bool push(std::string_view channel, const void* data, std::size_t size, int64_t receive_utime);

  // Consumer side: waits up to `timeout` for an event and swaps it into *out (whose buffers go
  // back to the slot for reuse). False on timeout, or when closed and empty.
  bool pop(QueuedEvent* out, std::chrono::milliseconds timeout);

  // Refuses further pushes and wakes the consumer; queued events can still be popped.
  void close();
  bool closedAndEmpty() const;

  EventQueueStats stats() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::vector<QueuedEvent> slots_;
  std::size_t max_bytes_;
  std::size_t head_ = 0;  // next slot to pop
  std::size_t count_ = 0;
  std::size_t bytes_ = 0;
  bool closed_ = false;
  EventQueueStats stats_;
};

}  // namespace sdlqr::logger
