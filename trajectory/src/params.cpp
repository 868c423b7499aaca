#include "sdlqr/trajectory/params.hpp"

#include "params_rows.hpp"

namespace sdlqr::trajectory {

TrajectoryParams::TrajectoryParams() { declaration().setDefaults(*this); }

const ParamTable<TrajectoryParams>& TrajectoryParams::declaration() {
  static const ParamTable<TrajectoryParams> table = [] {
    using P = TrajectoryParams;
    ParamTable<P> t = trajectoryParamsRows();
    t.check("check_dt", [](const P& p) { return p.check_dt <= p.sample_dt; }, "must be <= sample_dt");
    return t;
  }();
  return table;
}

SampleChecks TrajectoryParams::sampleChecks() const {
  SampleChecks checks;
  checks.max_position_jump = max_position_jump;
  return checks;
}

}  // namespace sdlqr::trajectory
