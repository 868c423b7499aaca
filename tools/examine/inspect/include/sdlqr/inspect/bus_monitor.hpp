#pragma once
// What `sdlqr-top` shows: per channel its message rate, the age of its newest message and its
// size; per process its newest HEARTBEAT (state, CPU, counters) and whether it is alive.
// Clock-free: the caller passes the receive time of every message and the time of each report.

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/logger/heartbeat_record.hpp"

namespace sdlqr::inspect {

struct ChannelRow {
  std::string channel;
  double rate_hz = 0.0;       // [Hz] messages over the last report period
  double age_ms = 0.0;        // [ms] since the newest message
  int64_t last_size = 0;      // [B] payload of the newest message
  int64_t messages = 0;       // since the monitor started
  double bytes_per_s = 0.0;   // [B/s] over the last report period
};

struct ProcessRow {
  std::string channel;        // HEARTBEAT channel it came on (carries the vehicle prefix)
  logger::HeartbeatRecord heartbeat;
  double age_s = 0.0;         // [s] since its newest heartbeat
  bool alive = false;         // heartbeat younger than the silence limit and not STOPPING
};

struct BusReport {
  int64_t utime = 0;          // [us] time of the report (receive clock)
  double period_s = 0.0;      // [s] covered by the rates
  std::vector<ChannelRow> channels;    // by name
  std::vector<ProcessRow> processes;   // by channel, then process name
};

class BusMonitor {
 public:
  // A process is alive while its newest heartbeat is younger than `silence_limit_s` (heartbeats
  // come at 1 Hz, so 2.5 s tolerates one lost).
  explicit BusMonitor(double silence_limit_s = 2.5) : silence_limit_s_(silence_limit_s) {}

  void onMessage(std::string_view channel, int64_t size, int64_t receive_utime);
  void onHeartbeat(std::string_view channel, const logger::HeartbeatRecord& heartbeat, int64_t receive_utime);

  // Rates cover the time since the previous report (or the first message).
  BusReport report(int64_t now_utime);

 private:
  struct ChannelStats {
    int64_t messages = 0;
    int64_t messages_at_report = 0;
    int64_t bytes = 0;
    int64_t bytes_at_report = 0;
    int64_t last_size = 0;
    int64_t last_utime = 0;
  };
  struct ProcessStats {
    logger::HeartbeatRecord heartbeat;
    int64_t last_utime = 0;
  };
  double silence_limit_s_;
  std::map<std::string, ChannelStats, std::less<>> channels_;
  std::map<std::pair<std::string, std::string>, ProcessStats> processes_;  // (channel, process)
  int64_t last_report_utime_ = -1;
  int64_t first_utime_ = -1;
};

// The report as fixed-width text: a channel table, a blank line, a process table.
std::string formatReport(const BusReport& report);

}  // namespace sdlqr::inspect
