#pragma once
// The one place where PX4's frames meet sdlqr's (every handler of the bridge and of the emulated
// PX4 converts through here, as mavros keeps ftf_frame_conversions.cpp):
//
//   PX4 (MAVLink)                          sdlqr (docs/architecture.md §3)
//   local frame NED: x north, y east, z down   world: x, y horizontal, z up (ENU: x east, y north)
//   body frame FRD: x front, y right, z down   body: x front, y left, z up (the thrust axis)
//   q (w, x, y, z) rotates FRD into NED        q (w, x, y, z) rotates body into world
//
//   position, velocity   world = (y, x, -z) of NED, and back the same way
//   body rates, vectors  body = (x, -y, -z) of FRD, and back the same way
//   attitude             q_world_body = q_ENU_NED * q_NED_FRD * q_FRD_FLU with q_ENU_NED =
//                        (0, √2/2, √2/2, 0) and q_FRD_FLU = (0, 1, 0, 0) (REP 103; mavros' NED_ENU_Q
//                        and AIRCRAFT_BASELINK_Q): written out (√2/2)(w + z, x + y, x - y, w - z),
//                        the same formula both ways
//   yaw                  yaw_world = π/2 - yaw_NED
//
// Hand-computed cases pin every one of these (tests/unit/px4/frames_test.cpp). Pure, no allocation.

#include "sdlqr/math/types.hpp"

namespace sdlqr::px4 {

// NED <-> sdlqr world (an involution: the same function maps back).
Vec3 nedToWorld(const Vec3& ned);
Vec3 worldToNed(const Vec3& world);
// FRD <-> sdlqr body (an involution).
Vec3 frdToBody(const Vec3& frd);
Vec3 bodyToFrd(const Vec3& body);
// q_NED_FRD (PX4) <-> q_world_body (sdlqr), both w, x, y, z.
Quat nedFrdToWorldBody(const Quat& q_ned_frd);
Quat worldBodyToNedFrd(const Quat& q_world_body);

}  // namespace sdlqr::px4
