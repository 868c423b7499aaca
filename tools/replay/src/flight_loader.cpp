#include "sdlqr/replay/flight_loader.hpp"

#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/decode.hpp"
#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::replay {

namespace {

template <class T>
bool append(const logger::LogEvent& event, std::vector<T>& series, LoadStats* stats) {
  T message;
  if (!logger::decodeMessage(event, &message)) {
    ++stats->decode_failures;
    return false;
  }
  series.push_back(std::move(message));
  ++stats->used;
  return true;
}

template <class T>
void appendInput(const logger::LogEvent& event, InputKind kind, std::vector<T>& series, RecordedFlight& flight,
                 LoadStats* stats) {
  if (append(event, series, stats)) flight.order.push_back({kind, static_cast<int32_t>(series.size() - 1)});
}

}  // namespace

RecordedFlight loadRecordedFlight(const std::string& path, const std::string& vehicle, LoadStats* stats) {
  *stats = LoadStats{};
  RecordedFlight flight;
  logger::LogReader reader(path);
  logger::LogEvent event;
  while (reader.next(&event)) {
    ++stats->events;
    const logger::ChannelName name = logger::splitChannel(event.channel);
    if (name.vehicle != vehicle) continue;
    const logger::ChannelType* type = logger::findChannelType(name.base);
    if (type == nullptr) continue;
    switch (type->type) {
      case logger::MessageType::kImu: appendInput(event, InputKind::kImu, flight.imu, flight, stats); break;
      case logger::MessageType::kVioPose: appendInput(event, InputKind::kVioPose, flight.vio_pose, flight, stats); break;
      case logger::MessageType::kStateEstimate:
        appendInput(event, InputKind::kStateEstimate, flight.state_estimate, flight, stats);
        break;
      case logger::MessageType::kCommand: appendInput(event, InputKind::kCommand, flight.command, flight, stats); break;
      case logger::MessageType::kTrajectory:
        appendInput(event, InputKind::kTrajectory, flight.trajectory, flight, stats);
        break;
      case logger::MessageType::kParams: appendInput(event, InputKind::kParams, flight.params, flight, stats); break;
      case logger::MessageType::kRateCommand: append(event, flight.rate_command, stats); break;
      case logger::MessageType::kReference: append(event, flight.reference, stats); break;
      case logger::MessageType::kGains: appendInput(event, InputKind::kGains, flight.gains, flight, stats); break;
      default: break;
    }
  }
  stats->complete = reader.status().complete();
  return flight;
}

}  // namespace sdlqr::replay
