#pragma once
// Settings of the gain solver process (section `gains:` of the vehicle file); weights, limits and
// method come from `lqr:`.

#include <string>

#include "sdlqr/config/config.hpp"

namespace sdlqr::gains {

struct GainsParams {
  double rate_hz = 10.0;           // [Hz] solve rate in simulation time (paper: 10 Hz)
  double state_timeout_s = 0.5;    // [s] no STATE_EST for this long (wall time): report DEGRADED

  static GainsParams load(const ConfigReader& gains);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr::gains
