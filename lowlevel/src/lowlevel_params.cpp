#include "sdlqr/lowlevel/lowlevel_params.hpp"

#include "lowlevel_params_rows.hpp"

namespace sdlqr::lowlevel {

LowlevelParams::LowlevelParams() { declaration().setDefaults(*this); }

const ParamTable<LowlevelParams>& LowlevelParams::declaration() {
  static const ParamTable<LowlevelParams> table = [] {
    using P = LowlevelParams;
    ParamTable<P> t = lowlevelParamsRows();
    t.check("dt_min", [](const P& p) { return p.dt_min < p.dt_max; }, "must be < dt_max");
    return t;
  }();
  return table;
}

std::string LowlevelParams::invalidReasonFor(const VehicleParams& vehicle, double gravity) const {
  if (!(idle_thrust >= vehicle.min_rotor_thrust && idle_thrust < vehicle.max_rotor_thrust)) {
    return "idle_thrust: must be within the rotor range [min_rotor_thrust, max_rotor_thrust)";
  }
  if (!(4.0 * idle_thrust < 0.5 * vehicle.mass * gravity)) return "idle_thrust: must stay below half the hover thrust";
  return {};
}

std::string LowlevelParams::invalidReasonFor(const ValidationLimits& limits) const {
  if (!(failsafe.max_rate <= limits.max_body_rate)) return "failsafe.max_rate: must be <= validation.max_body_rate";
  return {};
}

}  // namespace sdlqr::lowlevel
