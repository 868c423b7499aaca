#pragma once
// Settings of the 100 Hz state-dependent LQR process (section `controller:` of the vehicle file).

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/guard.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::controller {

// What the controller does with an uploaded TRAJECTORY whose samples ask beyond the vehicle.
enum class UploadBeyondLimits { kRefuse, kScale };

// Each member is declared once (key, unit, default, range, help) in
// controller/params/controller_params.yaml (the rules across keys: controller_params.cpp); the
// default constructor takes the defaults from there.
struct ControllerParams : DeclaredParams<ControllerParams> {
  double rate_hz;
  double max_prediction_s;  // longest an estimate is carried forward to a tick (0: never)
  double gains_stale_s;
  double gains_fallback_s;
  double max_position_error;  // norm bound on p - p_ref fed to K (paper §IV-A: bounded velocity)
  double max_velocity_error;
  double takeoff_speed;
  double landing_speed;
  double landed_speed;
  double landed_time;
  double landing_undershoot;
  // A controller (re)started while its first estimates show the vehicle this far above the ground
  // plane z = 0 of the world frame (the frame VIO and the simulator share) rejoins the flight in a
  // hold instead of waiting on the ground for a take-off.
  double rejoin_height;
  // A rejoin first levels and stops the vehicle (the reference at the vehicle itself), and holds
  // where it is once tilted at most recovery_tilt_deg and moving at most recovery_speed.
  double recovery_tilt_deg;
  double recovery_speed;
  ReferenceMode tracking;  // for trajectories that do not say
  UploadBeyondLimits trajectory_beyond_limits;  // refused with the report, or flown time-scaled
  trajectory::TrajectoryGuardParams guard;  // aborts a trajectory that flies the vehicle away
  trajectory::TransitionParams transition;  // entry into and exit from a trajectory
  // The law itself is lqr.law (the gain solver needs it too); these belong to the controller alone.
  double switch_time_s;    // bumpless transfer between laws (bumpless_transfer.hpp)
  double integral_limit;   // [m s] anti-windup bound on the norm of the position-error integral
  double integral_zone;    // [m] the integral only integrates within this distance of the reference
  double thrust_gain_time_constant;  // [s] sdlqr_adaptive: how slowly the thrust gain follows
  double thrust_gain_min;            // [-] sdlqr_adaptive: bounds of the thrust gain estimate
  double thrust_gain_max;
  double thrust_gain_zone;           // [m] sdlqr_adaptive: adapts only this close to the reference
  Vec3 geometric_position_gain;     // [1/s^2] geometric_control.hpp kp x, y, z
  Vec3 geometric_velocity_gain;     // [1/s] kd x, y, z
  Vec3 geometric_attitude_gain;     // [1/s] k_att roll, pitch, yaw

  ControllerParams();
  static const ParamTable<ControllerParams>& declaration();
};

}  // namespace sdlqr::controller
