#include "sdlqr/logger/heartbeat_record.hpp"

namespace sdlqr::logger {

std::string processStateName(int8_t state) {
  static const char* const kNames[] = {"STARTING", "RUNNING", "DEGRADED", "FAILSAFE", "STOPPING"};
  if (state >= 0 && state < 5) return kNames[state];
  return "UNKNOWN(" + std::to_string(state) + ")";
}

}  // namespace sdlqr::logger
