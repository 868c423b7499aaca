#pragma once
// Settings of the 100 Hz state-dependent LQR process (section `controller:` of the vehicle file).

#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::controller {

struct ControllerParams {
  double rate_hz = 100.0;             // [Hz] control rate in simulation time (paper: 100 Hz)
  double max_prediction_s = 0.005;    // [s] longest an estimate is carried forward to a tick (0: never)
  double gains_stale_s = 0.3;         // [s] GAINS older than this are flagged stale (3 missed updates)
  double gains_fallback_s = 1.0;      // [s] GAINS older than this: switch to the precomputed hover K
  double max_position_error = 1.0;    // [m] norm bound on p - p_ref fed to K (paper §IV-A: bounded velocity)
  double max_velocity_error = 2.0;    // [m/s] norm bound on v - v_ref fed to K
  double takeoff_speed = 0.5;         // [m/s] climb rate of the take-off reference
  double landing_speed = 0.4;         // [m/s] descent rate of the landing reference
  double landed_speed = 0.1;          // [m/s] below this, near the ground, for landed_time: landed
  double landed_time = 1.0;           // [s]
  double landing_undershoot = 0.3;    // [m] the landing reference continues this far below the ground
  // A controller (re)started while its first estimates show the vehicle this far above the ground
  // plane z = 0 of the world frame (the frame VIO and the simulator share) rejoins the flight in a
  // hold instead of waiting on the ground for a take-off.
  double rejoin_height = 0.2;         // [m]
  ReferenceMode tracking = ReferenceMode::kSpatial;  // for trajectories that do not say

  static ControllerParams load(const ConfigReader& controller);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr::controller
