#include "sdlqr/faults/kernel_loss.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>

namespace sdlqr::faults {

namespace {

constexpr std::string_view kLost = "lost.";

const logger::ChannelTimeline* timelineOf(const logger::FlightLog& log, const std::string& base) {
  const std::string name = log.vehicle.empty() ? base : log.vehicle + "/" + base;
  for (const logger::ChannelTimeline& c : log.channels) {
    if (c.channel == name) return &c;
  }
  return nullptr;
}

// Seqs missing from the log on one channel whose next message the recorder received at or before
// `until` [us wall] (the subscriber, hearing that message about then, had counted them).
int64_t gapsUntil(const logger::ChannelTimeline& c, int64_t until) {
  int64_t gaps = 0;
  for (size_t i = 1; i < c.seq.size(); ++i) {
    if (c.receive_utime[i] > until) break;
    if (c.seq[i] > c.seq[i - 1] + 1) gaps += c.seq[i] - c.seq[i - 1] - 1;
  }
  return gaps;
}

int64_t counter(const logger::HeartbeatRecord& hb, const std::string& name) {
  for (const auto& [key, value] : hb.counters) {
    if (key == name) return value;
  }
  return 0;
}

std::string text(const char* format, double a, double b = 0.0, double c = 0.0, double d = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof buffer, format, a, b, c, d);
  return buffer;
}

}  // namespace

std::vector<Finding> judgeKernelLoss(const logger::FlightLog& log, const Liveness& liveness, int64_t kernel_dropped) {
  std::vector<Finding> findings;
  findings.push_back({kernel_dropped > 0, "kernel drops: the loss rule's counter " + std::to_string(kernel_dropped) +
                                              " datagram(s) (must be > 0: the loss was active)"});
  // What the recorder lost on its own (its socket or its queue): gaps in the log no one else has.
  int64_t recorder_own = 0;
  std::map<std::string, const logger::HeartbeatRecord*> last;
  for (const ProcessLiveness& p : liveness.processes) {
    if (p.last_index < 0) continue;
    last[p.process] = &log.heartbeat[static_cast<size_t>(p.last_index)];
    if (p.process == "sdlqr-logger") {
      const logger::HeartbeatRecord& hb = *last[p.process];
      recorder_own = counter(hb, "bus.kernel_dropped") + counter(hb, "bus.over_capacity") + hb.dropped;
    }
  }
  // The log's gaps against the counter, over the channels with one publisher (seq per channel).
  int64_t gaps = 0, events = 0, heartbeats = 0;
  for (const logger::ChannelTimeline& c : log.channels) {
    events += c.events;
    if (c.lcm_type == "heartbeat_t") heartbeats += c.events;
    else gaps += gapsUntil(c, INT64_MAX);
  }
  const double share = events > 0 ? 1.0 - static_cast<double>(heartbeats) / static_cast<double>(events) : 0.0;
  const double expected = share * static_cast<double>(kernel_dropped);
  const double low = expected - 3.0 * std::sqrt(expected) - 2.0 * static_cast<double>(log.channels.size());
  const double high = static_cast<double>(kernel_dropped + recorder_own);
  findings.push_back({static_cast<double>(gaps) >= low && static_cast<double>(gaps) <= high,
                      text("kernel drops in the log: %.0f seq gaps on its single-publisher channels (the rule's "
                           "%.0f drops there: at least %.0f, at most %.0f with the recorder's own losses)",
                           static_cast<double>(gaps), expected, std::max(0.0, low), high)});
  for (const auto& [process, hb] : last) {
    if (process == "sdlqr-logger") continue;
    const auto at = static_cast<size_t>(hb - log.heartbeat.messages.data());
    const int64_t heard_until = log.heartbeat.receive_utime[at];
    for (const auto& [name, lost] : hb->counters) {
      if (name.compare(0, kLost.size(), kLost) != 0) continue;
      const std::string channel = name.substr(kLost.size());
      const logger::ChannelTimeline* timeline = timelineOf(log, channel);
      // Nothing logged to compare with, or a seq per publisher (HEARTBEAT).
      if (timeline == nullptr || timeline->seq.empty() || timeline->lcm_type == "heartbeat_t") continue;
      const int64_t in_log = gapsUntil(*timeline, heard_until);
      const int64_t counted = lost - counter(*hb, "queue_drop." + channel);
      findings.push_back({counted >= in_log - recorder_own - 1,
                          process + " " + channel + ": lost " + std::to_string(counted) +
                              " beyond its queue's drops, the log's gaps until its last heartbeat " +
                              std::to_string(in_log) + " (at least that, less the recorder's own " +
                              std::to_string(recorder_own) + " and 1)"});
    }
  }
  return findings;
}

}  // namespace sdlqr::faults
