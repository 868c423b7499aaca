#include "sdlqr/gains/gains_params.hpp"

namespace sdlqr::gains {

GainsParams::GainsParams() { declaration().setDefaults(*this); }

const ParamTable<GainsParams>& GainsParams::declaration() {
  static const ParamTable<GainsParams> table = [] {
    using P = GainsParams;
    ParamTable<P> t("gain solver (sdlqr-gains); weights, limits and method come from lqr");
    t.number("rate_hz", &P::rate_hz, 10.0, "Hz", Range::closed(0.1, 1000.0), "solve rate in simulation time (paper: 10 Hz; controller.rate_hz: a K for every controller tick)");
    t.number("state_timeout_s", &P::state_timeout_s, 0.5, "s", Range::above(0.0),
             "no STATE_EST for this long (wall time): report DEGRADED");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::gains
