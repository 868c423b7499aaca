#pragma once
// The one map from channel names to LCM message types (one type per channel) used by
// the reader, the CSV export and the metrics, from the channels of lcmtypes/*.lcm
// (sdlqr/messages/channels.hpp).

#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/health/stream.hpp"

namespace sdlqr::logger {

// The streams of common/health (one per channel); kOther and kCount name no message type.
using MessageType = ::sdlqr::Stream;

struct ChannelType {
  std::string_view base;       // channel without vehicle prefix, e.g. "IMU"
  MessageType type;
  std::string_view lcm_type;   // lcm-gen class name, e.g. "imu_t"
};

const std::vector<ChannelType>& channelTypes();

// nullptr when `base` is not one of ours.
const ChannelType* findChannelType(std::string_view base);

// "QUAD1/IMU" -> vehicle "QUAD1", base "IMU"; "IMU" -> vehicle "", base "IMU". The split is at
// the last '/', so a vehicle name may itself hold '/'.
struct ChannelName {
  std::string vehicle;
  std::string base;
};
ChannelName splitChannel(std::string_view channel);

}  // namespace sdlqr::logger
