#pragma once
// Reads the replay's inputs and the recorded outputs of one vehicle from an LCM event log.

#include <string>

#include "sdlqr/replay/recorded_flight.hpp"

namespace sdlqr::replay {

struct LoadStats {
  int64_t events = 0;           // every event of the log
  int64_t used = 0;             // events of the vehicle's replayed channels
  int64_t decode_failures = 0;
  bool complete = true;         // false when the log ends in a truncated event
};

// Throws logger::LogError (an std::invalid_argument) when the log cannot be read.
RecordedFlight loadRecordedFlight(const std::string& path, const std::string& vehicle, LoadStats* stats);

}  // namespace sdlqr::replay
