#include "sdlqr/controller/controller_params.hpp"

#include "sdlqr/math/in_flight.hpp"

#include "controller_params_rows.hpp"

namespace sdlqr::controller {

namespace {

// A row built in code (params/controller_params.yaml names it): the tracking key is declared once,
// by declareTracking, for every process that checks PARAMS.
void addTrackingRow(ParamTable<ControllerParams>& t) { declareTracking(t, &ControllerParams::tracking); }

}  // namespace

ControllerParams::ControllerParams() { declaration().setDefaults(*this); }

const ParamTable<ControllerParams>& ControllerParams::declaration() {
  static const ParamTable<ControllerParams> table = [] {
    using P = ControllerParams;
    ParamTable<P> t = controllerParamsRows();
    t.check("gains_fallback_s", [](const P& p) { return p.gains_fallback_s > p.gains_stale_s; }, "must be > gains_stale_s");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::controller
