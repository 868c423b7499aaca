#pragma once
// Internal: decoding one log event into an lcm-gen class, by the bus's own decode step (the size
// walk, then decode: common/bus decode.hpp), so a log is read as the processes read the bus.

#include "sdlqr/bus/decode.hpp"
#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::logger::detail {

template <class LcmType>
bool decodeEvent(const LogEvent& event, LcmType* out) {
  return event.size <= UINT32_MAX && bus::decode(event.data, static_cast<uint32_t>(event.size), *out) == RejectReason::kNone;
}

}  // namespace sdlqr::logger::detail
