#include "sdlqr/trajectory/guard.hpp"

namespace sdlqr::trajectory {

TrajectoryGuardParams::TrajectoryGuardParams() { declaration().setDefaults(*this); }

const ParamTable<TrajectoryGuardParams>& TrajectoryGuardParams::declaration() {
  static const ParamTable<TrajectoryGuardParams> table = [] {
    using P = TrajectoryGuardParams;
    ParamTable<P> t("trajectory guard: beyond these the trajectory is aborted into a hold where the vehicle is");
    t.number("max_path_error", &P::max_path_error, 1.0, "m", Range::above(0.0), "estimate to reference distance");
    t.number("max_speed", &P::max_speed, 6.0, "m/s", Range::above(0.0), "estimated speed");
    t.list("fence_min", &P::fence_min, {-10.0, -10.0, -1.0}, "m", Range::finite(), "geofence box, lower corner (world)");
    t.list("fence_max", &P::fence_max, {10.0, 10.0, 10.0}, "m", Range::finite(), "geofence box, upper corner (world)");
    t.check("fence_max", [](const P& p) { return (p.fence_max - p.fence_min).minCoeff() > 0.0; },
            "must exceed fence_min on every axis");
    return t;
  }();
  return table;
}

const char* toString(GuardTrip trip) {
  switch (trip) {
    case GuardTrip::kNone: return "none";
    case GuardTrip::kPathError: return "path error";
    case GuardTrip::kSpeed: return "speed";
    case GuardTrip::kGeofence: return "geofence";
  }
  return "?";
}

GuardTrip checkGuard(const TrajectoryGuardParams& guard, const Vec3& position, const Vec3& velocity,
                     const Vec3& reference_position) {
  const bool inside = (position - guard.fence_min).minCoeff() >= 0.0 && (guard.fence_max - position).minCoeff() >= 0.0;
  if (!inside) return GuardTrip::kGeofence;
  if (velocity.norm() > guard.max_speed) return GuardTrip::kSpeed;
  if ((position - reference_position).norm() > guard.max_path_error) return GuardTrip::kPathError;
  return GuardTrip::kNone;
}

}  // namespace sdlqr::trajectory
