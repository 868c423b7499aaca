#include "sdlqr/logger/channel_types.hpp"

#include "sdlqr/messages/channels.hpp"

namespace sdlqr::logger {

const std::vector<ChannelType>& channelTypes() {
  static const std::vector<ChannelType> table = {
      {channel::kImu, MessageType::kImu, "imu_t"},
      {channel::kVioPose, MessageType::kVioPose, "vio_pose_t"},
      {channel::kStateEstimate, MessageType::kStateEstimate, "state_estimate_t"},
      {channel::kRateCommand, MessageType::kRateCommand, "rate_cmd_t"},
      {channel::kMotorCommand, MessageType::kMotorCommand, "motor_cmd_t"},
      {channel::kGains, MessageType::kGains, "gains_t"},
      {channel::kReference, MessageType::kReference, "reference_t"},
      {channel::kTrajectory, MessageType::kTrajectory, "trajectory_t"},
      {channel::kDisturbance, MessageType::kDisturbance, "disturbance_t"},
      {channel::kParams, MessageType::kParams, "params_t"},
      {channel::kCommand, MessageType::kCommand, "command_t"},
      {channel::kHeartbeat, MessageType::kHeartbeat, "heartbeat_t"},
      {channel::kSimTruth, MessageType::kSimTruth, "sim_truth_t"},
      {channel::kSimClock, MessageType::kSimClock, "sim_clock_t"},
  };
  return table;
}

const ChannelType* findChannelType(std::string_view base) {
  for (const ChannelType& entry : channelTypes()) {
    if (entry.base == base) return &entry;
  }
  return nullptr;
}

ChannelName splitChannel(std::string_view channel) {
  const size_t slash = channel.rfind('/');
  if (slash == std::string_view::npos) return {std::string(), std::string(channel)};
  return {std::string(channel.substr(0, slash)), std::string(channel.substr(slash + 1))};
}

}  // namespace sdlqr::logger
