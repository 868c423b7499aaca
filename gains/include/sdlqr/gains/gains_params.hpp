#pragma once
// Settings of the gain solver process (section `gains:` of the vehicle file); weights, limits and
// method come from `lqr:`.

#include <string>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr::gains {

// Declared (key, unit, default, range, help) in GainsParams::declaration() (gains_params.cpp).
struct GainsParams {
  double rate_hz;
  double state_timeout_s;

  GainsParams();
  static const ParamTable<GainsParams>& declaration();
  static GainsParams load(const ConfigReader& gains) { return declaration().load(gains); }
  std::string invalidReason() const { return declaration().invalidReason(*this); }
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr::gains
