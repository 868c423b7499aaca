#pragma once
// A decoded HEARTBEAT as the plain record the log tools and sdlqr-top work with.

#include <algorithm>

#include "sdlqr/heartbeat_t.hpp"
#include "sdlqr/logger/heartbeat_record.hpp"

namespace sdlqr::logger {

inline HeartbeatRecord toHeartbeatRecord(const heartbeat_t& m) {
  HeartbeatRecord h;
  h.utime = m.utime;
  h.seq = m.seq;
  h.process = m.process;
  h.pid = m.pid;
  h.state = m.state;
  h.received = m.received;
  h.published = m.published;
  h.dropped = m.dropped;
  h.rejected = m.rejected;
  h.deadline_misses = m.deadline_misses;
  h.errors = m.errors;
  h.cpu_percent = m.cpu_percent;
  const size_t n = std::min(m.counter_names.size(), m.counter_values.size());
  for (size_t i = 0; i < n; ++i) h.counters.emplace_back(m.counter_names[i], m.counter_values[i]);
  h.last_error = m.last_error;
  return h;
}

}  // namespace sdlqr::logger
