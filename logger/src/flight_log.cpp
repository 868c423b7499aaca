#include "sdlqr/logger/flight_log.hpp"

#include <tuple>
#include <unordered_map>

#include "lcm_decode.hpp"
#include "sdlqr/logger/decode.hpp"
#include "sdlqr/messages/channels.hpp"
#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/log_reader.hpp"
#include "sdlqr/bus/convert.hpp"

namespace sdlqr::logger {

namespace {

template <class LcmType, class Plain>
bool decodeAs(const LogEvent& event, Plain* out) {
  LcmType message{};
  if (!detail::decodeEvent(event, &message)) return false;
  *out = bus::fromLcm(message);
  return true;
}

template <class LcmType, class Plain>
void decodeInto(const LogEvent& event, Series<Plain>& series, ChannelTimeline& timeline) {
  Plain message;
  if (!decodeAs<LcmType>(event, &message)) {
    ++series.decode_failures;
    ++timeline.decode_failures;
    return;
  }
  timeline.addDecoded(event.receive_utime, message.utime, message.seq);
  series.messages.push_back(std::move(message));
  series.receive_utime.push_back(event.receive_utime);
}

template <class Plain>
void decodeIfOfStream(Stream stream, const LogEvent& event, Series<Plain>& series, ChannelTimeline& timeline) {
  if (stream == streamOf<Plain>()) decodeInto<bus::LcmOf<Plain>>(event, series, timeline);
}

void decode(Stream stream, const LogEvent& e, FlightLog& log, ChannelTimeline& t) {
  std::apply([&](auto&... series) { (decodeIfOfStream(stream, e, series, t), ...); }, log.allSeries());
}

}  // namespace

void FlightLog::clear() {
  vehicle.clear();
  file = LogFileStatus();
  std::apply([](auto&... series) { (series.clear(), ...); }, allSeries());
  channels.clear();
}

template <class Plain>
bool decodeMessage(const LogEvent& event, Plain* out) {
  return decodeAs<bus::LcmOf<Plain>>(event, out);
}

namespace detail {
// decodeMessage<Msg> of every message type with a channel, for the other translation units (an
// object with external linkage keeps the instantiations it points at).
template <class... Msg>
constexpr auto decoders(MessageTypes<Msg...>) {
  return std::tuple{&decodeMessage<Msg>...};
}
extern const auto kDecoders = decoders(ChannelTypes{});
}  // namespace detail

FlightLog FlightLog::load(const std::string& path, const std::string& vehicle) {
  FlightLog log;
  log.vehicle = vehicle;
  LogReader reader(path);
  std::unordered_map<std::string, size_t> index;
  LogEvent event;
  while (reader.next(&event)) {
    const std::string name(event.channel);
    auto [it, inserted] = index.try_emplace(name, log.channels.size());
    const ChannelName split = splitChannel(name);
    const ChannelType* type = findChannelType(split.base);
    if (inserted) {
      ChannelTimeline timeline;
      timeline.channel = name;
      if (type) timeline.lcm_type = std::string(type->lcm_type);
      log.channels.push_back(std::move(timeline));
    }
    ChannelTimeline& timeline = log.channels[it->second];
    timeline.addEvent(event.receive_utime, event.size);
    if (type && split.vehicle == vehicle) decode(type->type, event, log, timeline);
  }
  log.file = reader.status();
  if (log.file.events == 0) {
    throw LogError("'" + path + "' holds no LCM event" +
                   std::string(log.file.file_bytes == 0 ? " (empty file)" : " (not an LCM event log?)"));
  }
  return log;
}

const ChannelTimeline* FlightLog::channel(std::string_view name) const {
  for (const ChannelTimeline& c : channels) {
    if (c.channel == name) return &c;
  }
  return nullptr;
}

MetricsInput FlightLog::metricsInput() const {
  MetricsInput input;
  input.log = file;
  input.channels = channels;
  if (!gains.empty()) input.gains[channel::name(vehicle, channel::kGains)] = gains.messages;
  if (!rate_command.empty()) input.rate_commands[channel::name(vehicle, channel::kRateCommand)] = rate_command.messages;
  if (!heartbeat.empty()) {
    input.heartbeats[channel::name(vehicle, channel::kHeartbeat)] = {heartbeat.messages, heartbeat.receive_utime};
  }
  return input;
}

}  // namespace sdlqr::logger
