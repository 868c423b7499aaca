#pragma once
// Everything the bodyrate loop reads from the `lowlevel:` section of the vehicle file. Each
// piece keeps its own struct next to its code; this one adds the loop-level values.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/attitude_filter.hpp"
#include "sdlqr/lowlevel/failsafe.hpp"
#include "sdlqr/lowlevel/ground_detector.hpp"
#include "sdlqr/lowlevel/input_checks.hpp"
#include "sdlqr/lowlevel/mixer.hpp"
#include "sdlqr/lowlevel/rate_control.hpp"

namespace sdlqr::lowlevel {

// Declared (key, unit, default, range, help) in lowlevel/params/lowlevel_params.yaml;
// each nested struct in its own file.
struct LowlevelParams : DeclaredParams<LowlevelParams> {
  double idle_thrust;
  double rate_cmd_timeout;
  double dt_min;
  double dt_max;
  double hover_thrust_time_constant;

  RateControlParams rate_control;
  MixerParams mixer;
  AttitudeFilterParams attitude_filter;
  GroundDetectorParams ground_detector;
  FailsafeParams failsafe;
  InputLimits input_limits;

  LowlevelParams();
  static const ParamTable<LowlevelParams>& declaration();
  // Checks against the airframe: the idle thrust must fit the rotors and not lift the vehicle.
  std::string invalidReasonFor(const VehicleParams& vehicle, double gravity) const;
  // Checks against the stack's message limits: the failsafe stays within the body-rate bound.
  std::string invalidReasonFor(const ValidationLimits& limits) const;
};

}  // namespace sdlqr::lowlevel
