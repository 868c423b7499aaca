#include "sdlqr/trajectory/guard.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/math/quaternion.hpp"

#include "guard_rows.hpp"

namespace sdlqr::trajectory {

TrajectoryGuardParams::TrajectoryGuardParams() { declaration().setDefaults(*this); }

const ParamTable<TrajectoryGuardParams>& TrajectoryGuardParams::declaration() {
  static const ParamTable<TrajectoryGuardParams> table = [] {
    using P = TrajectoryGuardParams;
    ParamTable<P> t = trajectoryGuardParamsRows();
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
    case GuardTrip::kTilt: return "tilt";
    case GuardTrip::kAttitudeError: return "attitude error";
  }
  return "?";
}

double attitudeError(const Quat& a, const Quat& b) {
  const double cosine_half = std::abs(a.normalized().dot(b.normalized()));
  return 2.0 * std::acos(std::min(1.0, cosine_half));
}

GuardTrip checkGuard(const TrajectoryGuardParams& guard, const State& estimate, const State& reference) {
  const Vec3 p = position(estimate);
  const bool inside = (p - guard.fence_min).minCoeff() >= 0.0 && (guard.fence_max - p).minCoeff() >= 0.0;
  if (!inside) return GuardTrip::kGeofence;
  if (velocity(estimate).norm() > guard.max_speed) return GuardTrip::kSpeed;
  constexpr double kDegree = M_PI / 180.0;
  const Quat q = orientation(estimate);
  if (quat::tilt(q) > guard.max_tilt_deg * kDegree) return GuardTrip::kTilt;
  if (attitudeError(q, orientation(reference)) > guard.max_attitude_error_deg * kDegree) {
    return GuardTrip::kAttitudeError;
  }
  if ((p - position(reference)).norm() > guard.max_path_error) return GuardTrip::kPathError;
  return GuardTrip::kNone;
}

}  // namespace sdlqr::trajectory
