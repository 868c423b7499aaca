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

// x_dot = f(x, u). The quaternion of x must be non-zero.
State dynamics(const State& x, const Input& u, double gravity = kDefaultGravity);

struct Linearization {
  StateMatrix A;  // df/dx at (x, u), eq. (16)
  InputMatrix B;  // df/du at (x, u), eq. (17)
};

// Gravity is constant in the world frame, so it does not appear in the Jacobians.
// thrust_gain theta: the model's produced over commanded thrust (v_dot = g + theta c R e_z; 1 in the
// paper). u's thrust is then the one produced (theta c), so A does not change with theta and B's
// thrust column is theta times the paper's.
Linearization linearize(const State& x, const Input& u, double thrust_gain = 1.0);

// d(q / ||q||)/dq, eq. (18).
Mat4 unitProjectionJacobian(const Quat& q);

}  // namespace sdlqr
