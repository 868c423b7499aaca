#pragma once
// Settings of the gain solver process (section `gains:` of the vehicle file); weights, limits and
// method come from `lqr:`.

#include <string>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr::gains {

// Declared (key, unit, default, range, help) in gains/params/gains_params.yaml.
struct GainsParams : DeclaredParams<GainsParams> {
  double rate_hz;
  double state_timeout_s;

  GainsParams();
  static const ParamTable<GainsParams>& declaration();
};

}  // namespace sdlqr::gains
