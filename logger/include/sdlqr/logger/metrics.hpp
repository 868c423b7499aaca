#pragma once
// Generic metrics of a recorded flight (metrics.json of `sdlqr-logger export`): per channel
// counts, rates and gaps on both clocks, sequence losses and pacing; GAINS solve statistics;
// RATE_CMD period jitter; the last HEARTBEAT of every process. Pure: plain data in, plain data
// out, no LCM.
//
// Two clocks are in a log. The receive time is the recorder's wall clock when the message
// arrived; utime is the simulation clock of the publisher. Their difference is meaningless on
// its own, so pacing is reported relative to an origin, the first message of the log that
// carries a simulation time (heartbeats excluded: their utime is "latest seen"):
//   lag = (receive - origin.receive) - (utime - origin.utime)
// A constant lag per channel means the bus keeps pace; the difference of median lags between
// two channels is the pipeline latency between them (e.g. IMU sample to RATE_CMD); the spread
// is delivery jitter; a lag that grows means the simulation runs slower than real time.

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/logger/heartbeat_record.hpp"
#include "sdlqr/logger/log_file_status.hpp"
#include "sdlqr/logger/statistics.hpp"

namespace sdlqr::logger {

// What the reader saw on one channel, in log order.
struct ChannelTimeline {
  std::string channel;
  std::string lcm_type;  // empty: not one of our channels (counted, not decoded)
  int64_t events = 0;
  int64_t bytes = 0;
  int64_t decode_failures = 0;
  std::vector<int64_t> event_receive_utime;  // [us] every event
  // Decoded messages (same length each).
  std::vector<int64_t> receive_utime;  // [us]
  std::vector<int64_t> utime;          // [us] simulation clock
  std::vector<int64_t> seq;

  void addEvent(int64_t receive, int64_t size) {
    ++events;
    bytes += size;
    event_receive_utime.push_back(receive);
  }
  void addDecoded(int64_t receive, int64_t message_utime, int64_t message_seq) {
    receive_utime.push_back(receive);
    utime.push_back(message_utime);
    seq.push_back(message_seq);
  }
};

struct HeartbeatSeries {
  std::vector<HeartbeatRecord> records;
  std::vector<int64_t> receive_utime;  // [us] same length
};

struct MetricsInput {
  LogFileStatus log;
  std::vector<ChannelTimeline> channels;
  std::map<std::string, std::vector<GainSet>> gains;              // by channel name (…/GAINS)
  std::map<std::string, std::vector<RateCommand>> rate_commands;  // by channel name (…/RATE_CMD)
  std::map<std::string, HeartbeatSeries> heartbeats;              // by channel name (…/HEARTBEAT)
};

struct MetricsOptions {
  double rate_command_period_s = 0.01;  // nominal controller period (docs/architecture.md §4: 100 Hz)
};

struct PacingOrigin {
  bool valid = false;
  std::string channel;
  int64_t receive_utime = 0;
  int64_t utime = 0;
};

struct ChannelMetrics {
  std::string channel;
  std::string lcm_type;
  int64_t events = 0;
  int64_t bytes = 0;
  int64_t decoded = 0;
  int64_t decode_failures = 0;
  // Receive clock, seconds since the first event of the log.
  double first_receive_s = 0.0;
  double last_receive_s = 0.0;
  double receive_rate_hz = 0.0;      // NaN with fewer than 2 events
  Distribution receive_interval_ms;  // max is the longest gap
  // Simulation clock of the decoded messages.
  int64_t first_utime = 0;
  int64_t last_utime = 0;
  double sim_duration_s = 0.0;
  double sim_rate_hz = 0.0;
  Distribution sim_interval_ms;
  int64_t utime_not_increasing = 0;  // messages whose utime is <= the one before
  // Sequence numbers.
  int64_t first_seq = 0;
  int64_t last_seq = 0;
  int64_t seq_lost = 0;      // sum of forward gaps
  int64_t seq_restarts = 0;  // backward jumps (publisher restarted)
  int64_t seq_repeats = 0;   // same seq twice in a row
  bool has_pacing = false;
  Distribution pacing_lag_ms;  // see the header comment
  // HEARTBEAT carries every process's heartbeat, each with its own seq and clock: the sim,
  // seq and pacing figures above would mix them, so they are left out (see the per-process
  // heartbeat metrics instead).
  bool several_publishers = false;
};

struct GainsMetrics {
  int64_t count = 0;
  Distribution solve_us;
  Distribution iterations;
  Distribution residual;
  std::map<std::string, int64_t> status;  // "ok", "not_converged", ...
  std::map<std::string, int64_t> method;  // "tangent", "iterative"
};

struct RateCommandMetrics {
  int64_t count = 0;
  double nominal_period_ms = 0.0;
  Distribution period_ms;  // consecutive utime differences (simulation clock), positive ones
  Distribution jitter_ms;  // |period - nominal|
  int64_t utime_not_increasing = 0;
  int64_t rate_saturated = 0;
  int64_t thrust_saturated = 0;
  std::map<std::string, int64_t> gains_status;  // "fresh", "stale", "fallback"
};

struct ProcessHeartbeatMetrics {
  std::string process;
  int64_t heartbeats = 0;
  int64_t distinct_pids = 0;  // > 1: the process was restarted during the log
  int64_t seq_lost = 0;       // heartbeats missing (forward seq gaps of one pid)
  double first_receive_s = 0.0;
  double last_receive_s = 0.0;
  double max_interval_s = 0.0;  // longest silence between two heartbeats (receive clock)
  HeartbeatRecord last;
};

struct LogMetrics {
  LogFileStatus log;
  PacingOrigin origin;
  std::string clock_channel;       // channel with the most decoded messages
  double real_time_factor = 0.0;   // its simulation span / receive span (1: paced at wall time)
  std::vector<ChannelMetrics> channels;  // by channel name
  std::map<std::string, GainsMetrics> gains;
  std::map<std::string, RateCommandMetrics> rate_commands;
  std::map<std::string, std::vector<ProcessHeartbeatMetrics>> heartbeats;  // by channel, then process name
};

LogMetrics computeLogMetrics(const MetricsInput& input, const MetricsOptions& options);

ChannelMetrics computeChannelMetrics(const ChannelTimeline& timeline, int64_t log_start_receive_utime,
                                     const PacingOrigin& origin);
GainsMetrics computeGainsMetrics(const std::vector<GainSet>& gains);
RateCommandMetrics computeRateCommandMetrics(const std::vector<RateCommand>& commands, double nominal_period_s);
std::vector<ProcessHeartbeatMetrics> computeHeartbeatMetrics(const HeartbeatSeries& series,
                                                             int64_t log_start_receive_utime);

// Valid JSON, keys in a fixed order, non-finite numbers as null.
void writeMetricsJson(std::ostream& out, const LogMetrics& metrics);

}  // namespace sdlqr::logger
