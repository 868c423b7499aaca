#pragma once
// Turns a scenario's trajectory request into the samples uploaded on TRAJECTORY, checked against
// the vehicle before the flight (trajectory/path_check.hpp).

#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/trajectory/guard.hpp"
#include "sdlqr/trajectory/params.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::mission {

// What a trajectory is checked against: the lqr input limits, the controller's guard (its speed
// bounds a path whose request names no v_max) and the controller's transitions.
struct PathLimits {
  LqrParams lqr;
  trajectory::TrajectoryGuardParams guard;
  trajectory::TransitionParams transition;
};

// `base` holds the vehicle file's trajectory settings; the request overrides laps, height and
// sample spacing. `hover` and `yaw`: where the vehicle is expected to hold when the trajectory
// starts (its entry is checked from there). Throws ConfigError naming `key` when the trajectory
// cannot be built or the check refuses it (a CSV file error names the file and line).
Trajectory buildTrajectory(const TrajectoryRequest& request, const trajectory::TrajectoryParams& base,
                           const PathLimits& limits, const Vec3& hover, double yaw, const std::string& key);

}  // namespace sdlqr::mission
