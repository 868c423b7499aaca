#pragma once
// Compares recomputed outputs with recorded ones, message by message (paired by seq) and field by
// field: bit for bit (doubles compared by their bits), and the largest absolute difference of
// every field that differs. GAINS.solve_us is excluded: it is the solver's wall time, measured by
// the process, not a function of the inputs.

#include <cstdint>
#include <string>
#include <vector>

#include "sdlqr/replay/recorded_flight.hpp"

namespace sdlqr::replay {

struct FieldDifference {
  std::string field;          // e.g. "body_rate[0]"
  int64_t messages = 0;       // messages in which it differs
  double max_abs = 0.0;       // largest |recorded - replayed|
};

struct ChannelComparison {
  std::string channel;        // STATE_EST, RATE_CMD, REFERENCE, GAINS
  int64_t recorded = 0;
  int64_t replayed = 0;
  int64_t compared = 0;       // seqs present in both
  int64_t identical = 0;      // bit for bit
  int64_t within_tolerance = 0;  // identical or every field within the tolerance
  int64_t only_recorded = 0;
  int64_t only_replayed = 0;
  // Recomputed after the last recorded message of the channel: the recorder stopped before the
  // process published it (the log's end cuts the flight at a different place on each channel).
  int64_t after_recording = 0;
  double max_abs = 0.0;       // over every field
  std::vector<FieldDifference> fields;  // only the fields that differ somewhere
  std::string first_difference;         // empty when none
  std::vector<std::string> excluded;    // fields not compared

  bool complete() const { return compared == recorded && compared + after_recording == replayed; }
  bool bitForBit() const { return complete() && identical == compared; }
  bool withinTolerance() const { return complete() && within_tolerance == compared; }
};

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
