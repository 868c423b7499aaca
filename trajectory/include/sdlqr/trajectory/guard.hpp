#pragma once
// The in-flight guard of a tracked trajectory: a reference beyond the vehicle must never fly it
// away. Each controller tick while tracking, the estimate is compared with the tick's reference;
// too far from the path, too fast, or outside the geofence box, and the controller aborts the
// trajectory into a hold at the current position (controller/reference_generator.cpp), counted
// as "trajectory.guard_abort" in the controller's HEARTBEAT.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::trajectory {

struct TrajectoryGuardParams {
  double max_path_error;  // [m] |p - p_ref|
  double max_speed;       // [m/s] |v|
  Vec3 fence_min;         // [m] world, geofence box corner
  Vec3 fence_max;

  TrajectoryGuardParams();
  static const ParamTable<TrajectoryGuardParams>& declaration();
};

enum class GuardTrip { kNone, kPathError, kSpeed, kGeofence };
const char* toString(GuardTrip trip);

// What trips first, in this order: the geofence, the speed, the path error.
GuardTrip checkGuard(const TrajectoryGuardParams& guard, const Vec3& position, const Vec3& velocity,
                     const Vec3& reference_position);

}  // namespace sdlqr::trajectory
