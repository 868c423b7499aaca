#pragma once
// The C++ generated from the MAVLink definitions: sdlqr/mavlink/messages.hpp (see its banner).

#include <string>

#include "sdlqr/mavlinkgen/definitions.hpp"

namespace sdlqr::mavlinkgen {

// `source_note` names the input files in the banner comment.
std::string emitMessagesHeader(const Definitions& definitions, const std::string& source_note);

}  // namespace sdlqr::mavlinkgen
