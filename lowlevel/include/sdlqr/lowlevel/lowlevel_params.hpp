#pragma once
// Everything the bodyrate loop reads from the `lowlevel:` section of the vehicle file. Each
// piece keeps its own struct next to its code; this one adds the loop-level values.

#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/attitude_filter.hpp"
#include "sdlqr/lowlevel/failsafe.hpp"
#include "sdlqr/lowlevel/ground_detector.hpp"
#include "sdlqr/lowlevel/input_checks.hpp"
#include "sdlqr/lowlevel/mixer.hpp"
#include "sdlqr/lowlevel/rate_control.hpp"

namespace sdlqr::lowlevel {

struct LowlevelParams {
  double idle_thrust = 0.03;                 // [N] per rotor while armed: rotors never stop in flight
  double rate_cmd_timeout = 0.1;             // [s] of IMU time without a valid RATE_CMD -> failsafe
  double dt_min = 0.000125;                  // [s] clamp of the IMU sample interval (PX4 does the same)
  double dt_max = 0.02;                      // [s]
  double hover_thrust_time_constant = 2.0;   // [s] learning the hover thrust from flown commands

  RateControlParams rate_control;
  MixerParams mixer;
  AttitudeFilterParams attitude_filter;
  GroundDetectorParams ground_detector;
  FailsafeParams failsafe;
  InputLimits input_limits;

  // Reads the given `lowlevel` mapping; throws ConfigError naming the key on a wrong value.
  static LowlevelParams load(const ConfigReader& lowlevel);
  // Empty when valid, else "key: reason" (nested keys dotted: "failsafe.descent_rate: ...").
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
  // Checks against the airframe: the idle thrust must fit the rotors and not lift the vehicle.
  std::string invalidReasonFor(const VehicleParams& vehicle, double gravity) const;
};

}  // namespace sdlqr::lowlevel
