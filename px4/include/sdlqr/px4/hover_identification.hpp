#pragma once
// The thrust mapping's hover throttle from a flight log (thrust_map.hpp, docs/px4.md): the
// normalized thrust each RATE_CMD became under the mapping flown, and the vertical acceleration
// and tilt of the estimate that followed, over the airborne near-hover part of the flight
// (|vertical speed| < 0.3 m/s, tilt < 10 deg, 0.3 m above the first estimate).

#include <ostream>
#include <string>
#include <vector>

#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/px4/bridge_params.hpp"

namespace sdlqr::px4 {

std::vector<HoverSample> hoverSamples(const logger::FlightLog& log, const ThrustMap& flown, double gravity);

// Prints "px4.thrust.hover_throttle: H" and the fit; returns 0, or 1 when no fit (the reason printed).
int identifyHover(const std::string& log_path, const BridgeParams& flown, double gravity, std::ostream& out);

}  // namespace sdlqr::px4
