#pragma once
// Compares the recomputed STATE_EST, RATE_CMD, REFERENCE and GAINS with the recorded ones (each
// channel by compareSeries, series_comparison.hpp) and prints the verdict.

#include <cstdint>
#include <string>
#include <vector>

#include "sdlqr/replay/recorded_flight.hpp"
#include "sdlqr/replay/series_comparison.hpp"

namespace sdlqr::replay {

struct Comparison {
  double tolerance = 0.0;
  std::vector<ChannelComparison> channels;
  bool bitForBit() const;
  bool withinTolerance() const;
};

Comparison compareOutputs(const RecordedFlight& recorded, const ReplayOutputs& replayed, double tolerance);

// A table (one line per channel), the first difference and the per-field maxima.
std::string formatComparison(const Comparison& comparison);

}  // namespace sdlqr::replay
