#pragma once
// The input streams a process counts rejections for: one per channel (one type per channel,
// common/messages/channels.hpp), named like the channel in lower case ("state_est").

#include <cstdint>
#include <string_view>

namespace sdlqr {

enum class Stream : int8_t {
  kImu = 0,
  kVioPose,
  kStateEstimate,
  kRateCommand,
  kMotorCommand,
  kGains,
  kReference,
  kTrajectory,
  kDisturbance,
  kParams,
  kCommand,
  kSimTruth,
  kHeartbeat,
  kSimClock,
  kOther,  // a channel of no known type (tests)
  kCount
};
inline constexpr int kStreamCount = static_cast<int>(Stream::kCount);

const char* streamName(Stream stream);          // "imu", "vio_pose", "state_est", ...
Stream streamOfChannel(std::string_view base);  // "STATE_EST" -> kStateEstimate; kOther if unknown

}  // namespace sdlqr
