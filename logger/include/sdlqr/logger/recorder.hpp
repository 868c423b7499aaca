#pragma once
// Writes received messages to a standard LCM event log (LCM's own event-log writer, so
// lcm-logplayer and LCM's tools read it) from a writer thread fed by an EventQueue: the
// caller's thread (the LCM handler) only copies. The file is flushed at least every
// flush_period, so killing the process (kill -9) loses at most that much. This is the I/O
// side of the logger; it has no bus.

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "sdlqr/logger/event_queue.hpp"

namespace sdlqr::logger {

struct RecorderOptions {
  std::string path;
  std::size_t queue_events = 16384;             // [-] ~16 s of the 1 kHz IMU alone
  std::size_t queue_bytes = 64u * 1024u * 1024u;  // [B] bound on queued payload
  std::chrono::milliseconds flush_period{200};
};

struct RecorderStats {
  int64_t queued = 0;
  int64_t dropped = 0;  // queue overflow
  int64_t written = 0;
  int64_t bytes_written = 0;  // payload bytes
  int64_t write_errors = 0;
  int64_t flushes = 0;
  int64_t max_queue_depth = 0;
  std::string last_error;
};

class Recorder {
 public:
  // Creates options.path exclusively: throws std::invalid_argument if it exists already or
  // cannot be created (missing folder, permissions), so nothing is ever overwritten.
  explicit Recorder(const RecorderOptions& options);
  ~Recorder();
  Recorder(const Recorder&) = delete;
  Recorder& operator=(const Recorder&) = delete;

  // From the receiving thread. False when the event was dropped (queue full or stopped).
  bool push(std::string_view channel, const void* data, std::size_t size, int64_t receive_utime) {
    return queue_.push(channel, data, size, receive_utime);
  }

  // Writes everything queued, flushes and closes the file. Idempotent.
  void stop();

  RecorderStats stats() const;
  const std::string& path() const { return path_; }

 private:
  void writerLoop();
  void flush();
  void noteError(const std::string& what);

  std::string path_;
  std::chrono::milliseconds flush_period_;
  EventQueue queue_;
  struct Log;
  std::unique_ptr<Log> log_;
  std::thread writer_;
  std::atomic<int64_t> written_{0};
  std::atomic<int64_t> bytes_written_{0};
  std::atomic<int64_t> write_errors_{0};
  std::atomic<int64_t> flushes_{0};
  mutable std::mutex error_mutex_;
  std::string last_error_;
  bool stopped_ = false;
};

}  // namespace sdlqr::logger
