#pragma once
// A HEARTBEAT message as a plain struct (heartbeat_t has no mirror in common/messages.hpp
// because only the logger and tools read heartbeats).

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sdlqr::logger {

struct HeartbeatRecord {
  int64_t utime = 0;  // [us] latest simulation time the process had seen
  int64_t seq = 0;
  std::string process;
  int32_t pid = 0;
  int8_t state = 0;  // heartbeat_t STATE_*
  int64_t received = 0;
  int64_t published = 0;
  int64_t dropped = 0;
  int64_t rejected = 0;
  int64_t deadline_misses = 0;
  int64_t errors = 0;
  double cpu_percent = 0.0;
  std::vector<std::pair<std::string, int64_t>> counters;
  std::string last_error;
};

// "STARTING", "RUNNING", "DEGRADED", "FAILSAFE", "STOPPING", or "UNKNOWN(<n>)".
std::string processStateName(int8_t state);

}  // namespace sdlqr::logger
