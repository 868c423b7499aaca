#pragma once
// Turns a scenario's trajectory request into the samples uploaded on TRAJECTORY.

#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::mission {

// `base` holds the vehicle file's trajectory settings; the request overrides laps, height and
// sample spacing. Throws ConfigError naming `key` when the trajectory cannot be built or fails
// its checks (a CSV file error names the file and line).
Trajectory buildTrajectory(const TrajectoryRequest& request, const trajectory::TrajectoryParams& base,
                           const LqrParams& lqr, const std::string& key);

}  // namespace sdlqr::mission
