#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::trajectory {

TrajectoryParams::TrajectoryParams() { declaration().setDefaults(*this); }

const ParamTable<TrajectoryParams>& TrajectoryParams::declaration() {
  static const ParamTable<TrajectoryParams> table = [] {
    using P = TrajectoryParams;
    ParamTable<P> t("trajectory generation and checking; defaults reproduce the paper's experiments (§III-C)");
    t.number("sample_dt", &P::sample_dt, 0.1, "s", Range::openClosed(0.0, 10.0),
             "sample spacing of generated trajectories (paper: 0.1 s)");
    t.number("check_dt", &P::check_dt, 0.001, "s", Range::above(0.0), "grid of the speed and input feasibility checks");
    t.number("height_offset", &P::height_offset, 1.0, "m", Range::finite(),
             "added to the paper's waypoint z (theirs start at the floor)");
    t.integer("laps", &P::laps, 2, "-", Range::closed(1, 100), "laps of the rest-to-rest min-snap path through p0..p3");
    t.flag("periodic", &P::periodic, false, "true: min-snap as one closed lap, repeated by the tracker");
    t.number("yaw", &P::yaw, 0.0, "rad", Range::finite(), "heading where waypoints give none");
    t.number("fast_v_max", &P::fast_v_max, 3.0, "m/s", Range::above(0.0), "min-snap of paper III-C.2");
    t.number("slow_v_max", &P::slow_v_max, 1.0, "m/s", Range::above(0.0),
             "min-snap of paper III-C.4 (disturbance experiment)");
    t.number("ellipse_speed", &P::ellipse_speed, 2.0, "m/s", Range::above(0.0), "infeasible ellipse of paper III-C.3");
    t.integer("ellipse_samples", &P::ellipse_samples, 36, "-", Range::closed(3, 100000),
              "ellipse samples per lap (d alpha = 2 pi / n)");
    t.number("max_position_jump", &P::max_position_jump, 1.0, "m", Range::above(0.0),
             "largest step between samples accepted from a file or the bus");
    t.number("accel_mismatch_max", &P::accel_mismatch_max, 0.5, "m/s^2", Range::above(0.0),
             "sampled references: inputs vs motion they should produce (feasibility.hpp)");
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
