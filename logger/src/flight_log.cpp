#include "sdlqr/logger/flight_log.hpp"

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

void decode(MessageType type, const LogEvent& e, FlightLog& log, ChannelTimeline& t) {
  switch (type) {
    case MessageType::kImu: decodeInto<imu_t>(e, log.imu, t); break;
    case MessageType::kVioPose: decodeInto<vio_pose_t>(e, log.vio_pose, t); break;
    case MessageType::kStateEstimate: decodeInto<state_estimate_t>(e, log.state_estimate, t); break;
    case MessageType::kRateCommand: decodeInto<rate_cmd_t>(e, log.rate_command, t); break;
    case MessageType::kMotorCommand: decodeInto<motor_cmd_t>(e, log.motor_command, t); break;
    case MessageType::kGains: decodeInto<gains_t>(e, log.gains, t); break;
    case MessageType::kReference: decodeInto<reference_t>(e, log.reference, t); break;
    case MessageType::kTrajectory: decodeInto<trajectory_t>(e, log.trajectory, t); break;
    case MessageType::kDisturbance: decodeInto<disturbance_t>(e, log.disturbance, t); break;
    case MessageType::kParams: decodeInto<params_t>(e, log.params, t); break;
    case MessageType::kCommand: decodeInto<command_t>(e, log.command, t); break;
    case MessageType::kHeartbeat: decodeInto<heartbeat_t>(e, log.heartbeat, t); break;
    case MessageType::kSimTruth: decodeInto<sim_truth_t>(e, log.sim_truth, t); break;
    case MessageType::kSimClock: decodeInto<sim_clock_t>(e, log.sim_clock, t); break;
    case MessageType::kOther:
    case MessageType::kCount: break;
  }
}

}  // namespace

void FlightLog::clear() {
  vehicle.clear();
  file = LogFileStatus();
  imu.clear();
  vio_pose.clear();
  state_estimate.clear();
  rate_command.clear();
  motor_command.clear();
  gains.clear();
  reference.clear();
  trajectory.clear();
  disturbance.clear();
  params.clear();
  command.clear();
  heartbeat.clear();
  sim_truth.clear();
  sim_clock.clear();
  channels.clear();
}

bool decodeMessage(const LogEvent& e, ImuSample* out) { return decodeAs<imu_t>(e, out); }
bool decodeMessage(const LogEvent& e, VioPose* out) { return decodeAs<vio_pose_t>(e, out); }
bool decodeMessage(const LogEvent& e, StateEstimate* out) { return decodeAs<state_estimate_t>(e, out); }
bool decodeMessage(const LogEvent& e, RateCommand* out) { return decodeAs<rate_cmd_t>(e, out); }
bool decodeMessage(const LogEvent& e, MotorCommand* out) { return decodeAs<motor_cmd_t>(e, out); }
bool decodeMessage(const LogEvent& e, GainSet* out) { return decodeAs<gains_t>(e, out); }
bool decodeMessage(const LogEvent& e, Reference* out) { return decodeAs<reference_t>(e, out); }
bool decodeMessage(const LogEvent& e, Trajectory* out) { return decodeAs<trajectory_t>(e, out); }
bool decodeMessage(const LogEvent& e, Disturbance* out) { return decodeAs<disturbance_t>(e, out); }
bool decodeMessage(const LogEvent& e, ParamsUpdate* out) { return decodeAs<params_t>(e, out); }
bool decodeMessage(const LogEvent& e, Command* out) { return decodeAs<command_t>(e, out); }
bool decodeMessage(const LogEvent& e, HeartbeatRecord* out) { return decodeAs<heartbeat_t>(e, out); }
bool decodeMessage(const LogEvent& e, SimTruth* out) { return decodeAs<sim_truth_t>(e, out); }
bool decodeMessage(const LogEvent& e, SimClockTick* out) { return decodeAs<sim_clock_t>(e, out); }

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
