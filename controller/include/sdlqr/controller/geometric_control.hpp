#pragma once
// The cascaded geometric tracking controller the paper argues against (its ref. [11]: Lee, Leok,
// McClamroch, "Geometric tracking control of a quadrotor UAV on SE(3)", 2010), in the body-rate
// form of Faessler et al. (2015) so that it outputs the same RATE_CMD as the LQR:
//
//   a_des = a_ref - kp e_p - kd e_v + g e_z         position PD (per axis) with the reference's acceleration
//   c     = a_des . z_B                             thrust along the current body z (clipped)
//   R_des = [x_d, y_d, z_d], z_d = a_des / |a_des|, heading of the reference's yaw
//   e_R   = 1/2 vee(R_des^T R - R^T R_des)          attitude error on SO(3)
//   omega = R^T R_des omega_ref - k_att e_R         body rates (k_att: roll, pitch, yaw)
//
// e_p and e_v are bounded as the LQR's (control_law.hpp), omega to omega_max. a_ref comes from the
// reference's attitude and thrust (zero in a hover setpoint). Pure, allocation-free.

#include "sdlqr/controller/control_law.hpp"

namespace sdlqr::controller {

struct GeometricGains {
  Vec3 position = Vec3::Zero();  // kp x, y, z (world) [1/s^2]
  Vec3 velocity = Vec3::Zero();  // kd x, y, z (world) [1/s]
  Vec3 attitude = Vec3::Zero();  // k_att roll, pitch, yaw (body) [1/s]
  double min_vertical_acceleration = 0.5;  // [m/s^2] a_des z never below this: a defined, upright z_d
};

ControlOutput geometricControl(const State& x, const State& x_ref, const Input& u_ref, const GeometricGains& gains,
                               const LqrParams& limits, const ErrorBounds& bounds);

}  // namespace sdlqr::controller
