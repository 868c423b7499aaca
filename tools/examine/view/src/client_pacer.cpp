#include "sdlqr/view/client_pacer.hpp"

#include <algorithm>

namespace sdlqr::view {

namespace {
// A timer firing a little early must not halve the rate: a frame may go 10 % of a period before it
// is due. Each frame moves the due time one period on, so over any stretch the mean rate stays at
// or under the cap; after a pause (no tick for over a period) the schedule restarts from now.
constexpr double kEarlyTolerance = 0.1;
}  // namespace

ClientPacer::Decision ClientPacer::onTick(double now_s, std::size_t buffered_bytes) {
  counters_.max_buffered_bytes = std::max(counters_.max_buffered_bytes, buffered_bytes);
  const double period = 1.0 / limits_.max_frame_rate_hz;
  if (now_s < next_due_s_ - kEarlyTolerance * period) return Decision::kTooSoon;
  next_due_s_ = now_s > next_due_s_ + period ? now_s + period : next_due_s_ + period;
  if (buffered_bytes > limits_.max_buffered_bytes) {
    ++counters_.frames_skipped;
    return Decision::kBacklogged;
  }
  return Decision::kSend;
}

void ClientPacer::sent(std::size_t bytes) {
  ++counters_.frames_sent;
  counters_.bytes_sent += bytes;
}

}  // namespace sdlqr::view
