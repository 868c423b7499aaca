// Lost messages per subscriber and channel: what each process counted from the seq gaps it saw
// (common/bus Node: "lost.<channel>", "queue_drop.<channel>" in HEARTBEAT), and what the recorder
// missed, from the gaps in the log.
#include <map>
#include <string_view>
#include <utility>

#include "flight_parts.hpp"

namespace sdlqr::analysis::detail {

namespace {

constexpr std::string_view kLost = "lost.";
constexpr std::string_view kQueueDrop = "queue_drop.";

bool startsWith(const std::string& text, std::string_view prefix) { return text.compare(0, prefix.size(), prefix) == 0; }

}  // namespace

std::vector<ChannelLoss> measureMessageLoss(const logger::FlightLog& log) {
  // Counters grow over a process's life and restart with it: the last heartbeat of each pid.
  std::map<std::pair<std::string, int32_t>, const logger::HeartbeatRecord*> last_of_pid;
  for (const logger::HeartbeatRecord& hb : log.heartbeat.messages) last_of_pid[{hb.process, hb.pid}] = &hb;
  std::map<std::pair<std::string, std::string>, ChannelLoss> by_channel;
  for (const auto& [key, hb] : last_of_pid) {
    for (const logger::HeartbeatCounter& c : hb->counters) {
      const bool lost = startsWith(c.name, kLost);
      if (!lost && !startsWith(c.name, kQueueDrop)) continue;
      const std::string channel = c.name.substr(lost ? kLost.size() : kQueueDrop.size());
      ChannelLoss& entry = by_channel[{hb->process, channel}];
      entry.process = hb->process;
      entry.channel = channel;
      (lost ? entry.lost : entry.queue_dropped) += c.value;
    }
  }
  std::vector<ChannelLoss> out;
  for (auto& [key, entry] : by_channel) out.push_back(entry);
  for (const logger::ChannelTimeline& c : log.channels) {
    const logger::ChannelMetrics m = logger::computeChannelMetrics(c, 0, logger::PacingOrigin{});
    if (m.several_publishers || c.seq.empty()) continue;  // HEARTBEAT: every process's own seq
    out.push_back(ChannelLoss{"log", c.channel, m.seq_lost, 0});
  }
  return out;
}

}  // namespace sdlqr::analysis::detail
