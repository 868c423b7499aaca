#pragma once
// The one check every trajectory gets before it is flown, whatever made it (a generator, a CSV
// file, a TRAJECTORY from elsewhere): the inputs of its samples within the limits (feasibility.hpp)
// and, with transitions enabled, a flyable entry from the hover the vehicle is expected in and a
// flyable stop from every sample it moves at (transition.hpp). The controller plans the real entry and
// exit from the state it finds; this check says, before the flight, that they exist.

#include <string>

#include "sdlqr/trajectory/feasibility.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::trajectory {

struct PathCheck {
  FeasibilityLimits limits;
  FeasibilityReport samples;
  bool entry_needed = false;   // the expected hover is not already at the path's start
  TransitionPlan entry;
  bool exit_needed = false;    // the path moves: leaving it needs a stop
  TransitionPlan exit;         // from the first sample with no stop, else from the fastest
  double exit_from_t = 0.0;    // [s] the time of that sample
  int exits_checked = 0;       // moving samples a stop was planned from
  int exits_missing = 0;       // of them, with no flyable stop
  bool transitions = false;    // entry and exit were checked (transitions enabled)

  bool feasible() const {
    return samples.feasible() && (!entry_needed || entry.found) && (!exit_needed || exit.found);
  }
};

// `hover` is the position the vehicle is expected to hold when the path starts (at rest, `yaw`).
PathCheck checkPath(const Trajectory& path, const FeasibilityLimits& limits, const Vec3& hover, double yaw,
                    const LqrParams& lqr, const TransitionParams& transition);

// One line: the limits the samples fail, then the entry and the exit ("... ; entry 2.1 s: thrust
// 7.9..12.2 m/s^2, max |omega| 1.2 rad/s, max speed 3.3 m/s; exit: a stop from each of 110 moving
// samples; from the fastest (2.6 s) 1.03 s: ..." or "exit: no stop from 11 of 150 moving samples;
// from the first (1.17 s): none within 20 s ...").
std::string describePathCheck(const PathCheck& check);

}  // namespace sdlqr::trajectory
