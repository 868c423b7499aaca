#pragma once
// Bounded hand-over from the LCM handler thread to the log writer thread. The handler copies
// into a slot preallocated for a typical message (kSlotBytes) and never waits for the writer:
// when the queue is full the event is dropped and counted, so a slow disk can never block the
// bus. A larger message (GAINS, HEARTBEAT, TRAJECTORY) gets a buffer of its own, which the slot
// gives back when it next takes a typical message, in the producer thread that allocated it; so
// the memory stays what it was at start. Slots that each kept the largest message they had ever
// held made the recorder's memory creep for half an hour; buffers freed by the writer thread
// instead still crept (glibc's per-thread caches) (docs/loss-and-starved.md, Soak).

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

  // Consumer side: waits up to `timeout` for an event and copies it into *out (whose buffers
  // grow once to the largest event). False on timeout, or when closed and empty.
  bool pop(QueuedEvent* out, std::chrono::milliseconds timeout);

  // Refuses further pushes and wakes the consumer; queued events can still be popped.
  void close();
  bool closedAndEmpty() const;

  EventQueueStats stats() const;
  // Bytes the slots hold in reserve (their buffers' capacities): back to the figure at
  // construction once every slot has taken a typical message again.
  std::size_t reservedBytes() const;

  static constexpr std::size_t kSlotBytes = 512;  // the log's messages but GAINS, HEARTBEAT, TRAJECTORY
  static constexpr std::size_t kSlotChannel = 64;  // LCM's longest channel name, with its NUL

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
