#pragma once
// Whether every process of a flight kept beating until the end of its log (sdlqr-faultcheck).
// Pure: a decoded FlightLog in, figures and verdicts out. Times are the recorder's wall clock.
//
// Only heartbeats that continue their own sender's sequence count: a process is a name and a pid
// whose seq grows by a few at a time. A hostile peer on the bus (sdlqr-fuzz-publisher) replays
// and mutates HEARTBEATs under real process names; those repeat or jump a seq, or start a pid
// that never beats twice, and are ignored — otherwise they could stand in for a process that hung.
//
// A process's silence is what it did not send while the bus carried the others' traffic. Every
// process of a stack beats once a second: a stretch of over kMachineStallS in which the recorder
// received nothing at all, from any process on any channel, is the machine's stall (seen in the
// suite: all heartbeats 2.8-2.9 s apart at once, the 1 kHz IMU silent as long), not one process's
// hang, and is not counted in a process's gaps. A process that hangs while the others go on still
// shows its whole silence.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "sdlqr/faults/finding.hpp"
#include "sdlqr/logger/flight_log.hpp"

namespace sdlqr::faults {

struct ProcessLiveness {
  std::string process;
  int64_t beats = 0;                 // heartbeats that continue their sender's sequence
  int64_t ignored = 0;               // replayed or forged (see above)
  int senders = 0;                   // pids that beat under this name (a restart adds one)
  int64_t first_receive_utime = -1;  // [us] wall
  int64_t last_receive_utime = -1;   // [us] wall
  double longest_gap_s = 0.0;        // [s] wall, between two counted heartbeats, machine stalls not counted
  double silent_at_end_s = 0.0;      // [s] wall: its last counted heartbeat -> the end of the log, likewise
  double stall_not_counted_s = 0.0;  // [s] the longest machine stall inside one of its gaps
  int8_t last_state = 0;             // heartbeat_t STATE_* of its last counted heartbeat
  std::ptrdiff_t last_index = -1;    // that heartbeat in log.heartbeat (its counters are the process's own)
};

// Longer than this without any datagram on the bus is a stall of the whole machine: every process
// beats once a second, so even one process left beating sends within it.
inline constexpr double kMachineStallS = 1.5;

struct Liveness {
  int64_t log_end_utime = -1;  // [us] wall: the last event the recorder received, of any channel
  double longest_machine_stall_s = 0.0;  // [s] wall: the longest machine stall (0: none)
  std::vector<ProcessLiveness> processes;  // by name
};

Liveness measureLiveness(const logger::FlightLog& log);

// The processes that end before the log does in every launch: the scenario player ends the run
// (policy `finish` in config/stack.procs) and the others stop after it; the launcher's
// `sdlqr-top --wait-for` ends once every process is up (beating, if that took over a second);
// the fuzz flight's publisher ends before the flight does.
inline const std::vector<std::string> kProcessesThatMayStop = {"sdlqr-fuzz-publisher", "sdlqr-mission", "sdlqr-top"};

struct LivenessRules {
  double max_silence_s = 2.5;           // longest gap, and longest silence before the log's end
  std::vector<std::string> expected;    // must have beaten at all
  std::vector<std::string> may_stop;    // may end early, if their last heartbeat says STOPPING
  std::vector<std::string> killed;      // killed on purpose: their gap is the outage
};

// One finding per process (its gap and its end) and per expected process that never beat.
std::vector<Finding> judgeLiveness(const Liveness& liveness, const LivenessRules& rules);

}  // namespace sdlqr::faults
