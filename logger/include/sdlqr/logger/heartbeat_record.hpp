#pragma once
// A HEARTBEAT message as a plain struct (generated from heartbeat_t.lcm, like every message:
// sdlqr::HeartbeatRecord), as the log tools and sdlqr-top work with it.

#include <cstdint>
#include <string>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr::logger {

using ::sdlqr::HeartbeatCounter;
using ::sdlqr::HeartbeatRecord;

// "STARTING", "RUNNING", "DEGRADED", "FAILSAFE", "STOPPING", or "UNKNOWN(<n>)".
std::string processStateName(int8_t state);

}  // namespace sdlqr::logger
