#pragma once
// One client's send rate cap: at most max_frame_rate frames a second, and no frame while the
// connection still holds more than max_buffered_bytes unsent (the client is slow or has stopped
// reading). A skipped frame is not queued: the next frame carries the newest messages then, so a
// stalled browser costs frames, never memory. Clock-free: the caller passes the time.

#include <cstddef>
#include <cstdint>

namespace sdlqr::view {

struct PacerLimits {
  double max_frame_rate_hz = 60.0;        // [1/s]
  std::size_t max_buffered_bytes = 1u << 20;  // [bytes] unsent on the connection before frames are skipped
};

struct PacerCounters {
  uint64_t frames_sent = 0;
  uint64_t frames_skipped = 0;       // due but the connection was still backlogged
  uint64_t bytes_sent = 0;
  std::size_t max_buffered_bytes = 0;  // the most the connection held unsent at a tick
};

class ClientPacer {
 public:
  enum class Decision { kSend, kTooSoon, kBacklogged };

  explicit ClientPacer(PacerLimits limits = {}) : limits_(limits) {}

  // At a tick at `now_s` [s] with `buffered_bytes` unsent: may a frame go out? kSend starts a new
  // frame period; kBacklogged counts a skipped frame.
  Decision onTick(double now_s, std::size_t buffered_bytes);
  // The frame sent after a kSend, of `bytes`.
  void sent(std::size_t bytes);
  const PacerCounters& counters() const { return counters_; }
  const PacerLimits& limits() const { return limits_; }

 private:
  PacerLimits limits_;
  PacerCounters counters_;
  double next_due_s_ = -1e300;  // [s] when the next frame may go
};

}  // namespace sdlqr::view
