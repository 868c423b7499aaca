#include "sdlqr/replay/flight_loader.hpp"

#include <algorithm>
#include <numeric>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/decode.hpp"
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

// An input of a process the replay recomputes: decoded by the bus's own step, and when that
// refuses it, kept as an undecodable input the cores count as the bus did.
template <class T>
void appendInput(const logger::LogEvent& event, const std::string& base, InputKind kind, std::vector<T>& series,
                 RecordedFlight& flight, LoadStats* stats) {
  bus::LcmOf<T> message;
  const RejectReason reason =
      event.size > UINT32_MAX ? RejectReason::kBadSize : bus::decode(event.data, static_cast<uint32_t>(event.size), message);
  if (reason != RejectReason::kNone) {
    ++stats->decode_failures;
    const int64_t utime = flight.order.empty() ? 0 : flight.utimeAt(flight.order.back());
    flight.undecodable.push_back({utime, streamOfChannel(base), reason});
    flight.order.push_back({InputKind::kUndecodable, static_cast<int32_t>(flight.undecodable.size() - 1)});
    return;
  }
  series.push_back(bus::fromLcm(message));
  ++stats->used;
  flight.order.push_back({kind, static_cast<int32_t>(series.size() - 1)});
}

// The recorder reads each port of the split bus on a socket of its own and, after a stall,
// writes one socket's backlog before another's: the log order is the order it handled them, the
// event's time the kernel's receive time. The inputs are replayed in the latter (stable: on one
// socket, and at equal times, log order), the order the processes on the bus received them in.
void orderByReceiveTime(RecordedFlight& flight, const std::vector<int64_t>& receive_utime) {
  std::vector<std::size_t> by_time(flight.order.size());
  std::iota(by_time.begin(), by_time.end(), std::size_t{0});
  std::stable_sort(by_time.begin(), by_time.end(),
                   [&](std::size_t a, std::size_t b) { return receive_utime[a] < receive_utime[b]; });
  std::vector<LogPosition> order;
  order.reserve(by_time.size());
  for (std::size_t i : by_time) order.push_back(flight.order[i]);
  flight.order = std::move(order);
}

}  // namespace

RecordedFlight loadRecordedFlight(const std::string& path, const std::string& vehicle, LoadStats* stats) {
  *stats = LoadStats{};
  RecordedFlight flight;
  logger::LogReader reader(path);
  logger::LogEvent event;
  std::vector<int64_t> receive_utime;  // of each entry of flight.order
  while (reader.next(&event)) {
    ++stats->events;
    const logger::ChannelName name = logger::splitChannel(event.channel);
    if (name.vehicle != vehicle) continue;
    const logger::ChannelType* type = logger::findChannelType(name.base);
    if (type == nullptr) continue;
    switch (type->type) {
      case logger::MessageType::kImu: appendInput(event, name.base, InputKind::kImu, flight.imu, flight, stats); break;
      case logger::MessageType::kVioPose: appendInput(event, name.base, InputKind::kVioPose, flight.vio_pose, flight, stats); break;
      case logger::MessageType::kStateEstimate:
        appendInput(event, name.base, InputKind::kStateEstimate, flight.state_estimate, flight, stats);
        break;
      case logger::MessageType::kCommand: appendInput(event, name.base, InputKind::kCommand, flight.command, flight, stats); break;
      case logger::MessageType::kTrajectory:
        appendInput(event, name.base, InputKind::kTrajectory, flight.trajectory, flight, stats);
        break;
      case logger::MessageType::kParams: appendInput(event, name.base, InputKind::kParams, flight.params, flight, stats); break;
      case logger::MessageType::kRateCommand: append(event, flight.rate_command, stats); break;
      case logger::MessageType::kReference: append(event, flight.reference, stats); break;
      case logger::MessageType::kGains: appendInput(event, name.base, InputKind::kGains, flight.gains, flight, stats); break;
      default: break;
    }
    receive_utime.resize(flight.order.size(), event.receive_utime);
  }
  orderByReceiveTime(flight, receive_utime);
  stats->complete = reader.status().complete();
  return flight;
}

}  // namespace sdlqr::replay
