#pragma once
// Internal: decoding one log event into an lcm-gen class. A message is accepted only when its
// bytes hold a complete encoding (checked first without allocating: see wire_check.hpp), it
// decodes, and it consumes exactly its bytes.

#include <algorithm>
#include <exception>

#include "sdlqr/heartbeat_t.hpp"
#include "sdlqr/logger/generated/lcm_csv_rows.hpp"
#include "sdlqr/logger/heartbeat_record.hpp"
#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::logger::detail {

template <class LcmType>
bool decodeEvent(const LogEvent& event, LcmType* out) {
  if (!generated::encodingFits(static_cast<const LcmType*>(nullptr), event.data, event.size)) return false;
  try {
    return out->decode(event.data, 0, static_cast<int>(event.size)) == event.size;
  } catch (const std::exception&) {
    return false;
  }
}

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

}  // namespace sdlqr::logger::detail
