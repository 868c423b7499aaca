#pragma once
// What the links between emulated hosts carried and cost, measured from flight logs (pure: logs
// in, figures out). Every namespace of a deployment shares the machine's one kernel clock, so
// receive times of recorders on different hosts compare directly.

#include <cstdint>
#include <string>
#include <vector>

#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/tables/statistics.hpp"

namespace sdlqr::deploy {

// Per message on an Ethernet-like link (1500-byte MTU): LCM short-message header (8) + channel + NUL on
// top of the payload, UDP (8), then IPv4 (20) and Ethernet (14 + 4 FCS) per IP fragment. Messages above
// one datagram (GAINS, TRAJECTORY) pay LCM's fragment header and the lower headers per fragment.
int64_t wireBytes(const std::string& channel, int64_t payload_bytes);

struct ChannelBandwidth {
  std::string channel;
  int64_t messages = 0;
  double rate_hz = 0.0;
  double payload_bytes_per_s = 0.0;  // what the log holds
  double wire_bytes_per_s = 0.0;     // with every header down to Ethernet (wireBytes)
};

// Every channel of the log, each over its own span (first to last receive), largest on the
// wire first; the last row is the total, channel "total" (the sum: what the segment carries).
std::vector<ChannelBandwidth> channelBandwidth(const logger::FlightLog& log);

struct CrossHostLatency {
  // [us] STATE_EST received on the controller's host -> the RATE_CMD computed from it received
  // on the lowlevel's host (the controller's work plus the hop).
  tables::Distribution state_to_command_us;
  // [us] RATE_CMD received on the controller's host -> the first MOTOR_CMD received on the
  // lowlevel's host after that RATE_CMD reached it (the hop plus the wait for the next IMU tick).
  tables::Distribution command_to_motor_us;
};
CrossHostLatency crossHostLatency(const logger::FlightLog& controller_host, const logger::FlightLog& lowlevel_host);

// What a recorder missed while a link was down [down_us, up_us] (recorder wall clock).
struct LinkGap {
  int64_t longest_gap_us = 0;      // longest silence of the channel overlapping the window
  int64_t received_inside = 0;     // messages received strictly inside the window, 50 ms margins
  int64_t missing = 0;             // seq numbers skipped
  int64_t missing_outside = 0;     // ... by jumps that do not span the window: lost elsewhere
};
LinkGap measureLinkGap(const logger::ChannelTimeline& channel, int64_t down_us, int64_t up_us);

// The lowlevel's failsafe.entries (a running count in its HEARTBEAT) around an outage.
struct FailsafeEntries {
  // Entered from its last heartbeat received before the link went down to its first one received
  // at least kFailsafeSettleUs after it came up: those the outage can have caused. -1 without
  // either heartbeat.
  int64_t around_outage = -1;
  int64_t whole_flight = -1;  // by its last heartbeat; -1 without one
};
constexpr int64_t kFailsafeSettleUs = 1'000'000;  // [us] a heartbeat period: a reaction shows by then
FailsafeEntries lowlevelFailsafeEntries(const logger::Series<HeartbeatRecord>& heartbeats, int64_t down_us,
                                        int64_t up_us);

}  // namespace sdlqr::deploy
