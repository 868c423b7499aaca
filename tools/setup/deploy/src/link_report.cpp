#include "sdlqr/deploy/link_report.hpp"

#include <algorithm>
#include <map>

namespace sdlqr::deploy {
namespace {

constexpr int64_t kUdpHeader = 8;
constexpr int64_t kPerFrame = 20 + 14 + 4;         // IPv4 header, Ethernet header + FCS, per frame
constexpr int64_t kIpPayloadPerFrame = 1500 - 20;  // a 1500-byte MTU
constexpr int64_t kMaxDatagramPayload = 65507;     // what one UDP datagram carries
constexpr int64_t kFragmentHeader = 20;            // LCM "LC03" header
constexpr int64_t kFragmentPayload = 65423;        // data per LCM fragment (LCM 1.3.1)

// A UDP datagram of `udp_payload` bytes on the wire, split into MTU-sized IP fragments.
int64_t datagramOnWire(int64_t udp_payload) {
  const int64_t ip_payload = udp_payload + kUdpHeader;
  const int64_t frames = (ip_payload + kIpPayloadPerFrame - 1) / kIpPayloadPerFrame;
  return ip_payload + frames * kPerFrame;
}

}  // namespace

int64_t wireBytes(const std::string& channel, int64_t payload_bytes) {
  const int64_t name = static_cast<int64_t>(channel.size()) + 1;
  const int64_t short_message = 8 + name + payload_bytes;
  if (short_message <= kMaxDatagramPayload) return datagramOnWire(short_message);
  int64_t total = 0;
  for (int64_t offset = 0, first = 1; offset < payload_bytes; offset += kFragmentPayload, first = 0) {
    const int64_t data = std::min(kFragmentPayload, payload_bytes - offset);
    total += datagramOnWire(kFragmentHeader + (first ? name : 0) + data);
  }
  return total;
}

std::vector<ChannelBandwidth> channelBandwidth(const logger::FlightLog& log) {
  std::vector<ChannelBandwidth> rows;
  ChannelBandwidth total;
  total.channel = "total";
  for (const logger::ChannelTimeline& c : log.channels) {
    ChannelBandwidth row;
    row.channel = c.channel;
    row.messages = c.events;
    const std::vector<int64_t>& t = c.event_receive_utime;
    // Over the channel's own span: a channel that starts with the simulator is not diluted by
    // the heartbeats before it.
    const double span_s = t.size() > 1 ? 1e-6 * static_cast<double>(t.back() - t.front()) : 0.0;
    if (span_s > 0.0) {
      row.rate_hz = static_cast<double>(t.size() - 1) / span_s;
      row.payload_bytes_per_s = row.rate_hz * static_cast<double>(c.bytes) / static_cast<double>(c.events);
      // Sizes of one channel barely vary: the mean message stands for each.
      row.wire_bytes_per_s = row.rate_hz * static_cast<double>(wireBytes(c.channel, c.bytes / c.events));
    }
    total.messages += row.messages;
    total.rate_hz += row.rate_hz;
    total.payload_bytes_per_s += row.payload_bytes_per_s;
    total.wire_bytes_per_s += row.wire_bytes_per_s;
    rows.push_back(row);
  }
  std::sort(rows.begin(), rows.end(),
            [](const ChannelBandwidth& a, const ChannelBandwidth& b) { return a.wire_bytes_per_s > b.wire_bytes_per_s; });
  rows.push_back(total);
  return rows;
}

CrossHostLatency crossHostLatency(const logger::FlightLog& controller_host, const logger::FlightLog& lowlevel_host) {
  std::map<int64_t, int64_t> state_at_controller;  // STATE_EST seq -> receive
  for (size_t i = 0; i < controller_host.state_estimate.size(); ++i) {
    state_at_controller[controller_host.state_estimate[i].seq] = controller_host.state_estimate.receive_utime[i];
  }
  std::map<int64_t, int64_t> command_at_controller;  // RATE_CMD seq -> receive
  for (size_t i = 0; i < controller_host.rate_command.size(); ++i) {
    command_at_controller[controller_host.rate_command[i].seq] = controller_host.rate_command.receive_utime[i];
  }
  const std::vector<int64_t>& motor = lowlevel_host.motor_command.receive_utime;
  std::vector<double> state_to_command, command_to_motor;
  for (size_t i = 0; i < lowlevel_host.rate_command.size(); ++i) {
    const RateCommand& command = lowlevel_host.rate_command[i];
    const int64_t arrived = lowlevel_host.rate_command.receive_utime[i];
    if (auto s = state_at_controller.find(command.state_seq); s != state_at_controller.end()) {
      state_to_command.push_back(static_cast<double>(arrived - s->second));
    }
    const auto sent = command_at_controller.find(command.seq);
    const auto next_motor = std::upper_bound(motor.begin(), motor.end(), arrived);
    if (sent != command_at_controller.end() && next_motor != motor.end()) {
      command_to_motor.push_back(static_cast<double>(*next_motor - sent->second));
    }
  }
  return {tables::describe(std::move(state_to_command)), tables::describe(std::move(command_to_motor))};
}

LinkGap measureLinkGap(const logger::ChannelTimeline& channel, int64_t down_us, int64_t up_us) {
  constexpr int64_t kMargin = 50'000;
  LinkGap gap;
  const std::vector<int64_t>& t = channel.event_receive_utime;
  for (size_t i = 0; i < t.size(); ++i) {
    if (t[i] > down_us + kMargin && t[i] < up_us - kMargin) ++gap.received_inside;
    if (i > 0 && t[i] >= down_us && t[i - 1] <= up_us) gap.longest_gap_us = std::max(gap.longest_gap_us, t[i] - t[i - 1]);
  }
  for (size_t i = 1; i < channel.seq.size(); ++i) {
    const int64_t skipped = channel.seq[i] - channel.seq[i - 1] - 1;
    if (skipped <= 0) continue;
    gap.missing += skipped;
    const bool spans_window = channel.receive_utime[i - 1] <= up_us && channel.receive_utime[i] >= down_us;
    if (!spans_window) gap.missing_outside += skipped;
  }
  return gap;
}

namespace {

int64_t failsafeEntriesOf(const HeartbeatRecord& heartbeat) {
  for (const HeartbeatCounter& counter : heartbeat.counters) {
    if (counter.name == "failsafe.entries") return counter.value;
  }
  return -1;
}

}  // namespace

FailsafeEntries lowlevelFailsafeEntries(const logger::Series<HeartbeatRecord>& heartbeats, int64_t down_us,
                                        int64_t up_us) {
  int64_t before = -1, after = -1;
  FailsafeEntries entries;
  for (size_t i = 0; i < heartbeats.size(); ++i) {
    if (heartbeats[i].process != "sdlqr-lowlevel") continue;
    const int64_t count = failsafeEntriesOf(heartbeats[i]);
    if (count < 0) continue;
    const int64_t received = heartbeats.receive_utime[i];
    if (received < down_us) before = count;
    if (after < 0 && received >= up_us + kFailsafeSettleUs) after = count;
    entries.whole_flight = count;
  }
  if (before >= 0 && after >= 0) entries.around_outage = after - before;
  return entries;
}

}  // namespace sdlqr::deploy
