#pragma once
// Decoding one log event into the plain struct of its channel, for tools that stream a log
// with LogReader instead of loading a whole FlightLog:
//
//   LogReader reader(path);
//   LogEvent event;
//   while (reader.next(&event)) {
//     if (splitChannel(event.channel).base != "IMU") continue;
//     ImuSample imu;
//     if (decodeMessage(event, &imu)) use(imu);
//   }
//
// False when the bytes are not a valid message of that type (wrong type, truncated, trailing
// bytes). The caller picks the type from the channel (channel_types.hpp).

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/logger/heartbeat_record.hpp"
#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::logger {

// Defined for every message type with a channel (sdlqr/messages/channels.hpp ChannelTypes).
template <class Plain>
bool decodeMessage(const LogEvent& event, Plain* out);

}  // namespace sdlqr::logger
