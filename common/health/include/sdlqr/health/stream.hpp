#pragma once
// The input streams a process counts rejections for: one per channel, named like the channel in
// lower case ("state_est"). The enum Stream is generated with the channels from lcmtypes/*.lcm
// (sdlqr/messages/channels.hpp); kOther is a channel of no known type (tests).

#include <string_view>

#include "sdlqr/messages/channels.hpp"

namespace sdlqr {

const char* streamName(Stream stream);          // "imu", "vio_pose", "state_est", ...
Stream streamOfChannel(std::string_view base);  // "STATE_EST" -> kStateEstimate; kOther if unknown

}  // namespace sdlqr
