#pragma once
// Rigid-body motion with full inertia (Newton-Euler) and one classic RK4 step. Forces are
// supplied by a callable evaluated at each RK4 stage, so state-dependent forces (rotor drag,
// the hold spring) and the motor-lag thrust inside the step are integrated to fourth order.

#include <Eigen/Geometry>  // cross

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::sim {

struct BodyState {
  Vec3 position = Vec3::Zero();      // [m] world, z up
  Quat orientation = identityQuat(); // body to world
  Vec3 velocity = Vec3::Zero();      // [m/s] world
  Vec3 body_rate = Vec3::Zero();     // [rad/s] body
};

struct Wrench {
  Vec3 force_world = Vec3::Zero();   // [N] everything but gravity
  Vec3 torque_body = Vec3::Zero();   // [N m]
};

struct BodyProperties {
  double mass = 1.0;                 // [kg]
  Vec3 inertia_diag = Vec3::Ones();  // [kg m^2] principal moments along body axes
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  // [m/s^2] world
};

// d/dt of BodyState, stored in the same layout.
struct BodyRate {
  Vec3 position;
  Quat orientation;
  Vec3 velocity;
  Vec3 body_rate;
};

inline BodyRate bodyDerivative(const BodyState& s, const Wrench& w, const BodyProperties& body) {
  BodyRate d;
  d.position = s.velocity;
  d.orientation = 0.5 * quat::multiply(s.orientation, quat::pure(s.body_rate));
  d.velocity = w.force_world / body.mass + body.gravity;
  const Vec3 momentum = body.inertia_diag.cwiseProduct(s.body_rate);
  d.body_rate = (w.torque_body - s.body_rate.cross(momentum)).cwiseQuotient(body.inertia_diag);
  return d;
}

inline BodyState advanced(const BodyState& s, const BodyRate& d, double h) {
  BodyState out;
  out.position = s.position + h * d.position;
  out.orientation = s.orientation + h * d.orientation;
  out.velocity = s.velocity + h * d.velocity;
  out.body_rate = s.body_rate + h * d.body_rate;
  return out;
}

// One RK4 step of length dt. wrench_at(state, tau) gives the wrench at time tau in [0, dt] into
// the step; stage states carry slightly non-unit quaternions, so it must normalize before
// rotating. The result is renormalized (RK4 drifts off the unit sphere by O(dt^5)).
template <class WrenchAt>
BodyState rk4Step(const BodyState& s, double dt, const BodyProperties& body, WrenchAt&& wrench_at) {
  const double half = 0.5 * dt;
  const BodyRate k1 = bodyDerivative(s, wrench_at(s, 0.0), body);
  const BodyState s2 = advanced(s, k1, half);
  const BodyRate k2 = bodyDerivative(s2, wrench_at(s2, half), body);
  const BodyState s3 = advanced(s, k2, half);
  const BodyRate k3 = bodyDerivative(s3, wrench_at(s3, half), body);
  const BodyState s4 = advanced(s, k3, dt);
  const BodyRate k4 = bodyDerivative(s4, wrench_at(s4, dt), body);

  const double w = dt / 6.0;
  BodyState out;
  out.position = s.position + w * (k1.position + 2.0 * k2.position + 2.0 * k3.position + k4.position);
  out.orientation =
      s.orientation + w * (k1.orientation + 2.0 * k2.orientation + 2.0 * k3.orientation + k4.orientation);
  out.orientation.normalize();
  out.velocity = s.velocity + w * (k1.velocity + 2.0 * k2.velocity + 2.0 * k3.velocity + k4.velocity);
  out.body_rate = s.body_rate + w * (k1.body_rate + 2.0 * k2.body_rate + 2.0 * k3.body_rate + k4.body_rate);
  return out;
}

}  // namespace sdlqr::sim
