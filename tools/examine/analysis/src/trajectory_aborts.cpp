#include "sdlqr/analysis/trajectory_aborts.hpp"

#include <limits>

namespace sdlqr::analysis {

namespace {

// The reference left a trajectory for a held setpoint without a new command.
bool aborts(const Reference& previous, const Reference& r) {
  return previous.trajectory_seq >= 0 && r.trajectory_seq < 0 && r.mode == ReferenceMode::kSetpoint &&
         r.command_seq == previous.command_seq;
}

}  // namespace

int64_t countTrajectoryAborts(const logger::FlightLog& log) {
  int64_t count = 0;
  const auto& references = log.reference.messages;
  for (size_t i = 1; i < references.size(); ++i) count += aborts(references[i - 1], references[i]);
  return count;
}

double trajectoryAbortTime(const logger::FlightLog& log, int64_t seq) {
  const auto& references = log.reference.messages;
  for (size_t i = 1; i < references.size(); ++i) {
    if (references[i - 1].trajectory_seq == seq && aborts(references[i - 1], references[i])) {
      return static_cast<double>(references[i].utime) * 1e-6;
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace sdlqr::analysis
