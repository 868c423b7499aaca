#include "sdlqr/health/stream.hpp"

#include "sdlqr/messages/channels.hpp"

namespace sdlqr {

namespace {

struct StreamChannel {
  Stream stream;
  std::string_view channel;
  const char* name;
};

// Each stream's channel and its name in counters, so the bus and the cores agree on both.
constexpr StreamChannel kStreams[] = {
    {Stream::kImu, channel::kImu, "imu"},
    {Stream::kVioPose, channel::kVioPose, "vio_pose"},
    {Stream::kStateEstimate, channel::kStateEstimate, "state_est"},
    {Stream::kRateCommand, channel::kRateCommand, "rate_cmd"},
    {Stream::kMotorCommand, channel::kMotorCommand, "motor_cmd"},
    {Stream::kGains, channel::kGains, "gains"},
    {Stream::kReference, channel::kReference, "reference"},
    {Stream::kTrajectory, channel::kTrajectory, "trajectory"},
    {Stream::kDisturbance, channel::kDisturbance, "disturbance"},
    {Stream::kParams, channel::kParams, "params"},
    {Stream::kCommand, channel::kCommand, "command"},
    {Stream::kSimTruth, channel::kSimTruth, "sim_truth"},
    {Stream::kHeartbeat, channel::kHeartbeat, "heartbeat"},
    {Stream::kSimClock, channel::kSimClock, "sim_clock"},
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
