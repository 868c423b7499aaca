#include "sdlqr/lowlevel/lowlevel_params.hpp"

namespace sdlqr::lowlevel {

LowlevelParams::LowlevelParams() { declaration().setDefaults(*this); }

const ParamTable<LowlevelParams>& LowlevelParams::declaration() {
  static const ParamTable<LowlevelParams> table = [] {
    using P = LowlevelParams;
    ParamTable<P> t("bodyrate loop (sdlqr-lowlevel): rate PID, mixer, arming, RATE_CMD-silent failsafe");
    t.number("idle_thrust", &P::idle_thrust, 0.03, "N", Range::atLeast(0.0),
             "per rotor while armed (rotors never stop in flight)");
    t.number("rate_cmd_timeout", &P::rate_cmd_timeout, 0.1, "s", Range::openClosed(0.0, 5.0),
             "of IMU time without a valid RATE_CMD -> failsafe");
    t.number("dt_min", &P::dt_min, 0.000125, "s", Range::openClosed(0.0, 0.1),
             "clamp of the IMU sample interval (PX4 does the same)");
    t.number("dt_max", &P::dt_max, 0.02, "s", Range::openClosed(0.0, 0.1), "upper clamp of the IMU sample interval");
    t.number("hover_thrust_time_constant", &P::hover_thrust_time_constant, 2.0, "s", Range::above(0.0),
             "learning the hover thrust from flown commands");
    t.section("rate_control", &P::rate_control);
    t.section("mixer", &P::mixer);
    t.section("attitude_filter", &P::attitude_filter);
    t.section("ground_detector", &P::ground_detector);
    t.section("failsafe", &P::failsafe);
    t.section("input_limits", &P::input_limits);
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
