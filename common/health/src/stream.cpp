#include "sdlqr/health/stream.hpp"

namespace sdlqr {

namespace {

struct StreamChannel {
  Stream stream;
  std::string_view channel;
  const char* name;
};

// The channel names of common/messages/channels.hpp (health sits below messages' channel list
// in no way but this one table, so the bus and the cores agree on each stream's name).
constexpr StreamChannel kStreams[] = {
    {Stream::kImu, "IMU", "imu"},
    {Stream::kVioPose, "VIO_POSE", "vio_pose"},
    {Stream::kStateEstimate, "STATE_EST", "state_est"},
    {Stream::kRateCommand, "RATE_CMD", "rate_cmd"},
    {Stream::kMotorCommand, "MOTOR_CMD", "motor_cmd"},
    {Stream::kGains, "GAINS", "gains"},
    {Stream::kReference, "REFERENCE", "reference"},
    {Stream::kTrajectory, "TRAJECTORY", "trajectory"},
    {Stream::kDisturbance, "DISTURBANCE", "disturbance"},
    {Stream::kParams, "PARAMS", "params"},
    {Stream::kCommand, "COMMAND", "command"},
    {Stream::kSimTruth, "SIM_TRUTH", "sim_truth"},
    {Stream::kHeartbeat, "HEARTBEAT", "heartbeat"},
};

}  // namespace

const char* streamName(Stream stream) {
  for (const StreamChannel& s : kStreams) {
    if (s.stream == stream) return s.name;
  }
  return "other";
}

Stream streamOfChannel(std::string_view base) {
  for (const StreamChannel& s : kStreams) {
    if (s.channel == base) return s.stream;
  }
  return Stream::kOther;
}

}  // namespace sdlqr
