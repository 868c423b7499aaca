#include "sdlqr/bus/paced_loop.hpp"

namespace sdlqr::bus {

namespace {

using Clock = std::chrono::steady_clock;

// Handles messages as they arrive until the deadline.
void serviceBusUntil(Node& node, Clock::time_point deadline) {
  while (node.running()) {
    const auto remaining = deadline - Clock::now();
    if (remaining <= Clock::duration::zero()) break;
    if (node.waitReadable(remaining)) node.spin(0);
  }
}

}  // namespace

int64_t runPaced(Node& node, const PacingOptions& options, const std::function<void()>& step) {
  const auto period = std::chrono::duration_cast<Clock::duration>(options.wall_period);
  Clock::time_point anchor = Clock::now();
  int64_t anchor_step = 0;
  int64_t misses = 0;
  for (int64_t done = 0; node.running() && (options.max_steps < 0 || done < options.max_steps); ++done) {
    const auto deadline = anchor + (done + 1 - anchor_step) * period;
    serviceBusUntil(node, deadline);
    if (!node.spin(0)) break;  // drains a last message and publishes the heartbeat when due
    const auto lateness = Clock::now() - deadline;
    if (lateness > period) {
      node.countDeadlineMiss();
      ++misses;
      if (lateness > options.max_catch_up_steps * period) {
        anchor = Clock::now();
        anchor_step = done + 1;
      }
    }
    step();
  }
  return misses;
}

}  // namespace sdlqr::bus
