#include "sdlqr/px4/frames.hpp"

#include <cmath>

namespace sdlqr::px4 {

Vec3 nedToWorld(const Vec3& ned) { return Vec3(ned[1], ned[0], -ned[2]); }
Vec3 worldToNed(const Vec3& world) { return Vec3(world[1], world[0], -world[2]); }
Vec3 frdToBody(const Vec3& frd) { return Vec3(frd[0], -frd[1], -frd[2]); }
Vec3 bodyToFrd(const Vec3& body) { return Vec3(body[0], -body[1], -body[2]); }

namespace {
// q_ENU_NED * q * q_FRD_FLU, multiplied out; the product is its own inverse map.
Quat swapFrames(const Quat& q) {
  const double h = std::sqrt(0.5);
  return Quat(h * (q[0] + q[3]), h * (q[1] + q[2]), h * (q[1] - q[2]), h * (q[0] - q[3]));
}
}  // namespace

Quat nedFrdToWorldBody(const Quat& q_ned_frd) { return swapFrames(q_ned_frd); }
Quat worldBodyToNedFrd(const Quat& q_world_body) { return swapFrames(q_world_body); }

}  // namespace sdlqr::px4
