#pragma once
// The newest message of each channel and source, and nothing older: what the view draws. The bus
// thread puts every message it hears (or the log player every event it passes); the server thread
// takes those that changed since it last looked, at its own pace (at most 60 frames a second).
// A channel has one source but HEARTBEAT, which every process of a vehicle publishes on: there the
// source is the process (sourceOf), so one process's beat never hides another's. A message
// replaces its slot's previous one in place, so a slow reader costs frames, never memory: the
// store holds at most max_slots messages of at most max_message_bytes each, and refuses (and
// counts) what would exceed either. Thread-safe.

#include <cstddef>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>
#include <string_view>
#include <vector>

namespace sdlqr::view {

struct StoredMessage {
  std::string channel;
  std::string source;         // "" but on HEARTBEAT: the process
  int64_t receive_utime = 0;  // [us] wall clock of its arrival (the log's time when playing a log)
  uint64_t version = 0;       // the store's counter when it was put: later puts, larger versions
  std::vector<uint8_t> bytes;
};

struct StoreStats {
  uint64_t puts = 0;
  uint64_t refused_slots = 0;  // messages of a channel or source past max_slots
  uint64_t refused_size = 0;   // messages over max_message_bytes
  std::size_t slots = 0;
};

class LatestStore {
 public:
  explicit LatestStore(std::size_t max_slots = 1024, std::size_t max_message_bytes = 4u << 20)
      : max_slots_(max_slots), max_message_bytes_(max_message_bytes) {}

  // False when refused (counted in stats()). `source`: sourceOf(channel, data, size).
  bool put(std::string_view channel, std::string_view source, int64_t receive_utime, const void* data, std::size_t size);
  // Copies every slot put after version `since` into *out (reusing its buffers; out is resized
  // to the count) and returns the newest version, to pass as `since` next time.
  uint64_t changedSince(uint64_t since, std::vector<StoredMessage>* out) const;
  // Forgets every message (a log seeked); versions keep counting up.
  void clear();
  StoreStats stats() const;

 private:
  std::size_t max_slots_;
  std::size_t max_message_bytes_;
  mutable std::mutex mutex_;
  std::vector<StoredMessage> slots_;
  std::map<std::string, std::size_t, std::less<>> index_;  // "<channel>\0<source>" -> slot
  std::string key_;  // put()'s, reused
  uint64_t version_ = 0;
  StoreStats stats_;
};

// The source of a message: on a HEARTBEAT channel the process that sent it ("" when the bytes are
// not one whole heartbeat), on any other channel "".
std::string sourceOf(std::string_view channel, const void* data, std::size_t size);

}  // namespace sdlqr::view
