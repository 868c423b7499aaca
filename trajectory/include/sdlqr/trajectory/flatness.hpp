#pragma once
// Differential flatness of the paper's model (eq. 3), after Mellinger & Kumar (ICRA 2011): the
// flat outputs p(t) and yaw(t) and their derivatives give the full reference state
// x_des = [p, q, v] and the feed-forward input u_des = [omega, c] that fly it exactly.
//
// Conventions of the project: world z up, gravity [0, 0, -g], Hamilton q (w, x, y, z) body to
// world, body z the thrust axis, c mass-normalized.
//   thrust vector  t = a + g e_z,  c = ||t||,  z_b = t / c
//   heading        x_b is perpendicular to y_c = [-sin yaw, cos yaw, 0], so the body x axis
//                  projects onto the world x-y plane along yaw exactly (ZYX yaw == quat::yaw(q)):
//                  x_b = (y_c x z_b) / ||y_c x z_b||,  y_b = z_b x x_b
//   body rates     z_b' = (j - (z_b . j) z_b) / c = omega_y x_b - omega_x y_b
//                  d/dt (x_b . y_c) = 0 gives omega_z = (yaw' (x_b . x_c) + omega_y (z_b . y_c)) / (y_b . y_c)
// Singular where c = 0 (free fall) or z_b is parallel to y_c (90 degrees of roll); there the
// reference falls back to the last well-defined attitude (level at zero thrust) and zero rates,
// and the feasibility check flags c < c_min long before.

#include "sdlqr/math/model.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::trajectory {

// Position and yaw with the derivatives the flat map needs, at time t.
struct FlatOutput {
  double t = 0.0;                     // [s]
  Vec3 position = Vec3::Zero();       // [m] world
  Vec3 velocity = Vec3::Zero();       // [m/s]
  Vec3 acceleration = Vec3::Zero();   // [m/s^2]
  Vec3 jerk = Vec3::Zero();           // [m/s^3]
  Vec3 snap = Vec3::Zero();           // [m/s^4]
  double yaw = 0.0;                   // [rad]
  double yaw_rate = 0.0;              // [rad/s]
};

struct FlatReference {
  State x = State::Zero();  // [p, q, v]
  Input u = Input::Zero();  // [omega (body), c]
  bool singular = false;    // c ~ 0 or 90 degrees of roll: attitude and rates not defined
};

FlatReference flatToReference(const FlatOutput& flat, double gravity);

// The same flat outputs flown against linear rotor drag (model.hpp RotorDrag, the plant's): the
// thrust vector is c z_b = a + g e_z + s(c) R D R^T v, implicit in R and c and solved by a fixed
// point from the drag-free attitude; the rates from its derivative (j plus the drag's rate along the
// reference, omega and c' on both sides, a few fixed-point steps). No drag: the map above, bit for bit.
FlatReference flatToReference(const FlatOutput& flat, double gravity, const RotorDrag& drag);

// Unit quaternion (w, x, y, z) of a rotation matrix, w >= 0.
Quat quaternionFromRotation(const Mat3& rotation);

}  // namespace sdlqr::trajectory
