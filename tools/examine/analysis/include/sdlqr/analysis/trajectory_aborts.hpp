#pragma once
// Trajectories the controller's guard aborted (trajectory/guard.hpp), read from the log alone: the
// REFERENCE leaves a trajectory for a setpoint while the last COMMAND it names stays the same (a
// GOTO or LAND that ends a trajectory names a newer command). On the bus the controller's
// HEARTBEAT counts the same events as "trajectory.guard_abort".

#include <cstdint>

#include "sdlqr/logger/flight_log.hpp"

namespace sdlqr::analysis {

int64_t countTrajectoryAborts(const logger::FlightLog& log);

// [s] simulation time the guard aborted the trajectory of `seq` into a hold (during its entry or
// along it); NaN when it did not.
double trajectoryAbortTime(const logger::FlightLog& log, int64_t seq);

}  // namespace sdlqr::analysis
