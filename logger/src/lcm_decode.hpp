#pragma once
// Internal: decoding one log event into an lcm-gen class. A message is accepted only when its
// bytes hold a complete encoding (checked first without allocating: see
// sdlqr/lcmtypes/wire_cursor.hpp), it decodes, and it consumes exactly its bytes.

#include <exception>

#include "sdlqr/lcmtypes/generated/wire_fits.hpp"
#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::logger::detail {

template <class LcmType>
bool decodeEvent(const LogEvent& event, LcmType* out) {
  if (!lcmtypes::encodingFits(static_cast<const LcmType*>(nullptr), event.data, event.size)) return false;
  try {
    return out->decode(event.data, 0, static_cast<int>(event.size)) == event.size;
  } catch (const std::exception&) {
    return false;
  }
}

}  // namespace sdlqr::logger::detail
