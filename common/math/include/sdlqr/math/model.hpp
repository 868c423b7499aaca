#pragma once
// The paper's quadrotor model, eq. (3), with body rates and mass-normalized thrust as inputs,
// and its analytic Jacobians, eq. (16)-(23), derived here (the printed eq. (21)-(23) carry
// sign and factor errors; the unit tests compare against central finite differences).
//
// The quaternion enters through q_u = q / ||q|| (eq. 18), so f is defined for any non-zero q and
// its Jacobian with respect to q contains the projection (I - q q^T / ||q||^2) / ||q||.

#include "sdlqr/math/types.hpp"

namespace sdlqr {

inline constexpr double kDefaultGravity = 9.81;  // [m/s^2]

// Linear rotor drag as the plant applies it (sim/src/rotors.cpp): the mass-normalized force
// -s R D R^T v, D = diag(coefficients) per body axis, s = sqrt(c / g) the rotor speed over its hover
// speed (the plant's mean of sqrt(T_i / T_hover) at equal rotor thrusts; 0 at c <= 0). Zero
// coefficients (the default): the paper's model, whose every result stays bit for bit.
struct RotorDrag {
  Vec3 coefficients = Vec3::Zero();  // [1/s] mass-normalized, body x, y, z
  double gravity = kDefaultGravity;  // [m/s^2] the coefficients hold at hover thrust c = g
  bool active() const { return (coefficients.array() != 0.0).any(); }
  // s(c) and ds/dc.
  double rotorSpeedRatio(double thrust) const;
  double rotorSpeedRatioSlope(double thrust) const;
};

// -s(c) R D R^T v [m/s^2] for the unit quaternion q_unit, world velocity v and thrust c.
Vec3 rotorDragAcceleration(const Quat& q_unit, const Vec3& velocity, double thrust, const RotorDrag& drag);

// x_dot = f(x, u), with the rotor drag when given. The quaternion of x must be non-zero.
State dynamics(const State& x, const Input& u, double gravity = kDefaultGravity, const RotorDrag& drag = {});

struct Linearization {
  StateMatrix A;  // df/dx at (x, u), eq. (16)
  InputMatrix B;  // df/du at (x, u), eq. (17)
};

// Gravity is constant in the world frame, so it does not appear in the Jacobians.
// thrust_gain theta: the model's produced over commanded thrust (v_dot = g + theta c R e_z; 1 in the
// paper). u's thrust is then the one produced (theta c), so A does not change with theta and B's
// thrust column is theta times the paper's.
// drag: the rotor drag's terms (A's velocity and attitude columns, B's thrust column through s(c));
// none adds nothing to the paper's Jacobians.
Linearization linearize(const State& x, const Input& u, double thrust_gain = 1.0, const RotorDrag& drag = {});

// d(q / ||q||)/dq, eq. (18).
Mat4 unitProjectionJacobian(const Quat& q);

}  // namespace sdlqr
