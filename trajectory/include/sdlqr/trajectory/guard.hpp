#pragma once
// The in-flight guard of a tracked trajectory: a reference beyond the vehicle must never fly it
// away, and a vehicle that diverges from it must not be lost. Each controller tick while tracking
// (or flying an entry or exit, transition.hpp), the estimate is compared with the tick's
// reference; outside the geofence box, too fast, tilted too far, turned too far from the
// reference's attitude, or too far from the path, and the controller aborts the trajectory into a
// recovery that levels and stops the vehicle, then holds where it stopped
// (controller/reference_generator.cpp), counted as "trajectory.guard_abort" in the controller's
// HEARTBEAT. Tilt and attitude error see a diverging flight before its position error grows: the
// velocity-step entry of a fast circle tilted to 79 degrees and crashed within 1 m of its path.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::trajectory {

struct TrajectoryGuardParams {
  double max_path_error;          // [m] |p - p_ref|
  double max_speed;               // [m/s] |v|
  double max_tilt_deg;            // [deg] angle of body z from world z
  double max_attitude_error_deg;  // [deg] rotation angle from the reference attitude
  Vec3 fence_min;                 // [m] world, geofence box corner
  Vec3 fence_max;

  TrajectoryGuardParams();
  static const ParamTable<TrajectoryGuardParams>& declaration();
};

enum class GuardTrip { kNone, kPathError, kSpeed, kGeofence, kTilt, kAttitudeError };
const char* toString(GuardTrip trip);

// What trips first, in this order: the geofence, the speed, the tilt, the attitude error, the path
// error. `estimate` and `reference` are full states [p, q, v].
GuardTrip checkGuard(const TrajectoryGuardParams& guard, const State& estimate, const State& reference);

// [rad] the rotation angle between two attitudes (either sign of either quaternion).
double attitudeError(const Quat& a, const Quat& b);

}  // namespace sdlqr::trajectory
