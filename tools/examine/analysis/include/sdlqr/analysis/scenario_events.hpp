#pragma once
// What a flight was expected to do, from its scenario: one entry per event (arm, take-off, each
// jump, each pull, each trajectory, parameter changes, the landing, a throw), each looked up in
// the log. The analysis judges these, not whatever messages it happens to find: an event whose
// message never reached the recorder is a failed check that names it ("pull +y at 39.0 s:
// DISTURBANCE not in the log"), never a window quietly left out.
//
// An event's message is the first one on its channel that matches it (command type and setpoint,
// disturbance mode and duration) at or after the event's time and before the next event of the same
// channel is due. The mission re-sends TAKEOFF and GOTO once a second with the same seq, so a
// command whose first copy was lost is found in its re-send, late.

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::analysis {

struct ExpectedEvent {
  enum class Kind { kArm, kDisarm, kTakeoff, kGoto, kLand, kPull, kParams, kTrajectory, kThrow };
  Kind kind = Kind::kGoto;
  std::string label;    // the scenario's label, else the kind ("takeoff"); unique within the flight
  std::string channel;  // where its message is published: COMMAND, DISTURBANCE, PARAMS, TRAJECTORY
  double at = 0.0;      // [s] simulation time the scenario plays it (a throw: the hand lets go)
  const mission::ScenarioEvent* source = nullptr;  // nullptr for a throw (the mission's own ARM)
  // A pull that the scenario plays while a trajectory is being tracked: judged against the path.
  bool on_trajectory = false;
  double seen = std::numeric_limits<double>::quiet_NaN();  // [s] its message's time; NaN: not in the log
  std::ptrdiff_t message = -1;  // index of that message in its channel's series

  bool found() const { return message >= 0; }
  // "pull +y at 39.0 s: DISTURBANCE not in the log"; for a found event, where it was.
  std::string describe() const;
};

// Every event of the scenario in time order, with unique labels, nothing looked up yet.
std::vector<ExpectedEvent> expectedEvents(const mission::Scenario& scenario);

// Looks each event up in the log (sets seen and message).
void findInLog(std::vector<ExpectedEvent>& events, const logger::FlightLog& log);

}  // namespace sdlqr::analysis
