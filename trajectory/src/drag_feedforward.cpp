#include "sdlqr/trajectory/drag_feedforward.hpp"

#include <cmath>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/flatness.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::trajectory {

namespace {

// The heading rate of body rates omega on attitude r at heading yaw: the flat map's
// omega_z = (yaw' (x_b . x_c) + omega_y (z_b . y_c)) / (y_b . y_c), solved for yaw'.
double headingRate(const Mat3& r, const Vec3& omega, double yaw) {
  const Vec3 x_c(std::cos(yaw), std::sin(yaw), 0.0);
  const Vec3 y_c(-std::sin(yaw), std::cos(yaw), 0.0);
  const double along = r.col(0).dot(x_c);
  if (std::abs(along) < 1e-6) return 0.0;
  return (omega.z() * r.col(1).dot(y_c) - omega.y() * r.col(2).dot(y_c)) / along;
}

}  // namespace

void compensateRotorDrag(State& x, Input& u, double gravity, const RotorDrag& drag) {
  if (!drag.active()) return;
  const Quat q = orientation(x).normalized();
  const FlatState state = flatStateOf(x, u, 0.0, gravity);
  FlatOutput flat;
  flat.position = state.position;
  flat.velocity = state.velocity;
  flat.acceleration = state.acceleration;
  flat.jerk = state.jerk;
  flat.yaw = state.yaw;
  flat.yaw_rate = headingRate(quat::rotationMatrix(q), bodyRate(u), state.yaw);
  const FlatReference with_drag = flatToReference(flat, gravity, drag);
  if (with_drag.singular) return;
  Quat q_drag = orientation(with_drag.x);
  if (q_drag.dot(q) < 0.0) q_drag = -q_drag;
  orientation(x) = q_drag;
  u = with_drag.u;
}

Input flownInput(const State& x, const Input& u, double gravity, const RotorDrag& drag) {
  State flown_x = x;
  Input flown_u = u;
  compensateRotorDrag(flown_x, flown_u, gravity, drag);
  return flown_u;
}

}  // namespace sdlqr::trajectory
