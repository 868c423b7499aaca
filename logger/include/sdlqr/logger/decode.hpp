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

bool decodeMessage(const LogEvent& event, ImuSample* out);
bool decodeMessage(const LogEvent& event, VioPose* out);
bool decodeMessage(const LogEvent& event, StateEstimate* out);
bool decodeMessage(const LogEvent& event, RateCommand* out);
bool decodeMessage(const LogEvent& event, MotorCommand* out);
bool decodeMessage(const LogEvent& event, GainSet* out);
bool decodeMessage(const LogEvent& event, Reference* out);
bool decodeMessage(const LogEvent& event, Trajectory* out);
bool decodeMessage(const LogEvent& event, Disturbance* out);
bool decodeMessage(const LogEvent& event, ParamsUpdate* out);
bool decodeMessage(const LogEvent& event, Command* out);
bool decodeMessage(const LogEvent& event, HeartbeatRecord* out);
bool decodeMessage(const LogEvent& event, SimTruth* out);
bool decodeMessage(const LogEvent& event, SimClockTick* out);

}  // namespace sdlqr::logger
