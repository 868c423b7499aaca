#include "sdlqr/lowlevel/lowlevel_params.hpp"

#include <cmath>

#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::lowlevel {

LowlevelParams LowlevelParams::load(const ConfigReader& lowlevel) {
  lowlevel.allowOnly({"idle_thrust", "rate_cmd_timeout", "dt_min", "dt_max", "hover_thrust_time_constant",
                      "rate_control", "mixer", "attitude_filter", "ground_detector", "failsafe", "input_limits"});
  LowlevelParams params;
  lowlevel.read("idle_thrust", params.idle_thrust);
  lowlevel.read("rate_cmd_timeout", params.rate_cmd_timeout);
  lowlevel.read("dt_min", params.dt_min);
  lowlevel.read("dt_max", params.dt_max);
  lowlevel.read("hover_thrust_time_constant", params.hover_thrust_time_constant);
  params.rate_control = RateControlParams::load(lowlevel.child("rate_control"));
  params.mixer = MixerParams::load(lowlevel.child("mixer"));
  params.attitude_filter = AttitudeFilterParams::load(lowlevel.child("attitude_filter"));
  params.ground_detector = GroundDetectorParams::load(lowlevel.child("ground_detector"));
  params.failsafe = FailsafeParams::load(lowlevel.child("failsafe"));
  params.input_limits = InputLimits::load(lowlevel.child("input_limits"));
  throwIfInvalid(lowlevel, params.invalidReason());
  return params;
}

std::string LowlevelParams::invalidReason() const {
  if (!(idle_thrust >= 0.0 && std::isfinite(idle_thrust))) return "idle_thrust: must be finite and >= 0";
  if (!(rate_cmd_timeout > 0.0 && rate_cmd_timeout <= 5.0)) return "rate_cmd_timeout: must be in (0, 5] s";
  // dt_max first: an invalid dt_max must be named, not blamed on dt_min.
  if (!(dt_max > 0.0 && dt_max <= 0.1)) return "dt_max: must be in (0, 0.1] s";
  if (!(dt_min > 0.0 && dt_min < dt_max)) return "dt_min: must be in (0, dt_max)";
  if (!(hover_thrust_time_constant > 0.0 && std::isfinite(hover_thrust_time_constant))) {
    return "hover_thrust_time_constant: must be > 0";
  }
  std::string reason = nestedReason("rate_control", rate_control.invalidReason());
  if (reason.empty()) reason = nestedReason("mixer", mixer.invalidReason());
  if (reason.empty()) reason = nestedReason("attitude_filter", attitude_filter.invalidReason());
  if (reason.empty()) reason = nestedReason("ground_detector", ground_detector.invalidReason());
  if (reason.empty()) reason = nestedReason("failsafe", failsafe.invalidReason());
  if (reason.empty()) reason = nestedReason("input_limits", input_limits.invalidReason());
  return reason;
}

std::string LowlevelParams::invalidReasonFor(const VehicleParams& vehicle, double gravity) const {
  if (!(idle_thrust >= vehicle.min_rotor_thrust && idle_thrust < vehicle.max_rotor_thrust)) {
    return "idle_thrust: must be within the rotor range [min_rotor_thrust, max_rotor_thrust)";
  }
  if (!(4.0 * idle_thrust < 0.5 * vehicle.mass * gravity)) return "idle_thrust: must stay below half the hover thrust";
  return {};
}

}  // namespace sdlqr::lowlevel
