#include "sdlqr/analysis/trajectory_aborts.hpp"

namespace sdlqr::analysis {

int64_t countTrajectoryAborts(const logger::FlightLog& log) {
  int64_t aborts = 0;
  const Reference* previous = nullptr;
  for (const Reference& r : log.reference.messages) {
    if (previous && previous->trajectory_seq >= 0 && r.trajectory_seq < 0 && r.mode == ReferenceMode::kSetpoint &&
        r.command_seq == previous->command_seq) {
      ++aborts;
    }
    previous = &r;
  }
  return aborts;
}

}  // namespace sdlqr::analysis
