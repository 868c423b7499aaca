#pragma once
// Physical description of the airframe, shared by the simulator (the plant) and the bodyrate
// loop (its model of the plant). Defaults: the paper's 255 g, 250 mm-diagonal quadrotor with a
// thrust-to-weight ratio of about 2 (§III-A).

#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr {

using Mat34 = Eigen::Matrix<double, 3, 4>;
using Mat44 = Eigen::Matrix<double, 4, 4>;

struct VehicleParams {
  double mass = 0.255;                            // [kg]
  Vec3 inertia_diag = Vec3(9.0e-4, 9.0e-4, 1.6e-3);  // [kg m^2] principal moments, body axes
  double arm_length = 0.125;                      // [m] centre to rotor axis (250 mm diagonal / 2)
  double max_rotor_thrust = 1.25;                 // [N] per rotor: 4 x 1.25 N = 2.0 x weight
  double min_rotor_thrust = 0.0;                  // [N] per rotor
  double torque_coefficient = 0.0125;             // [m] rotor drag torque per newton of thrust
  double motor_time_constant = 0.03;              // [s] first-order lag from command to thrust
  Vec3 rotor_drag = Vec3(0.30, 0.30, 0.10);       // [1/s] linear rotor drag, mass-normalized, body axes
  // Rotor i sits at (x, y) in the body frame (x forward, y left, z up); yaw_sign[i] * c_tau * T_i
  // is its reaction torque about body z. X layout, PX4 order: front-right, back-left, front-left, back-right.
  Eigen::Matrix<double, 2, 4> rotor_xy = defaultRotorPositions(0.125);
  Vec4 yaw_sign = Vec4(-1.0, -1.0, 1.0, 1.0);  // CCW rotors (FR, BL) push the body about -z

  static Eigen::Matrix<double, 2, 4> defaultRotorPositions(double arm_length);

  // [collective thrust; torque x; torque y; torque z] = effectiveness() * rotor thrusts.
  Mat44 effectiveness() const;
  Mat3 inertia() const { return inertia_diag.asDiagonal(); }
  double hoverThrustPerRotor(double gravity) const { return mass * gravity / 4.0; }

  // Reads the `vehicle` mapping; arm_length alone also sets the X layout unless rotor_xy is given.
  static VehicleParams load(const ConfigReader& vehicle);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr
