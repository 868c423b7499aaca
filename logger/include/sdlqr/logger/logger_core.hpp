#pragma once
// The logger process, bus-free: every received message into the Recorder's queue (the writer
// thread does the I/O), the newest simulation time heard, and the recorder's statistics in the
// health that HEARTBEAT reports (logger.written, .bytes, .queue_overflow, .write_errors,
// .flushes, .queue_max_depth). sdlqr-logger binds every channel to onMessage().

#include <cstdint>
#include <string>

#include "sdlqr/health/process_health.hpp"
#include "sdlqr/logger/recorder.hpp"

namespace sdlqr::logger {

class LoggerCore {
 public:
  // Throws std::invalid_argument when the log cannot be created (see Recorder).
  explicit LoggerCore(const RecorderOptions& options);

  // From the receiving thread: queued, or counted as dropped when the queue is full.
  void onMessage(const std::string& channel, const void* data, uint32_t size, int64_t receive_utime);
  // Wall time [s]: mirrors the recorder's statistics every 0.1 s.
  void onWallTime(double now_s);
  // Writes everything queued and closes the file; the final statistics are in the health.
  void stop();

  const Recorder& recorder() const { return recorder_; }
  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }

 private:
  void mirrorStats();

  Recorder recorder_;
  ProcessHealth health_;
  int64_t latest_utime_ = 0;
  double next_stats_s_ = -1.0;
  Counters::Id written_, bytes_, overflow_, write_errors_, flushes_, max_depth_;
};

}  // namespace sdlqr::logger
