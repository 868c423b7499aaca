#pragma once
// Physical description of the airframe, shared by the simulator (the plant) and the bodyrate
// loop (its model of the plant). Defaults: the paper's 255 g, 250 mm-diagonal quadrotor with a
// thrust-to-weight ratio of about 2 (§III-A).

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr {

using Mat34 = Eigen::Matrix<double, 3, 4>;
using Mat44 = Eigen::Matrix<double, 4, 4>;

// Each member is declared once (key, unit, default, range, help) in common/math/params/vehicle.yaml
// (the rules across keys: vehicle.cpp); the default constructor takes the defaults from there.
struct VehicleParams : DeclaredParams<VehicleParams> {
  double mass;
  Vec3 inertia_diag;  // principal moments, body axes
  double arm_length;
  double max_rotor_thrust;
  double min_rotor_thrust;
  double torque_coefficient;
  double motor_time_constant;
  Vec3 rotor_drag;
  // Rotor i sits at (x, y) in the body frame (x forward, y left, z up); yaw_sign[i] * c_tau * T_i
  // is its reaction torque about body z. X layout, PX4 order: front-right, back-left, front-left, back-right.
  Eigen::Matrix<double, 2, 4> rotor_xy;
  Vec4 yaw_sign;

  VehicleParams();
  static const ParamTable<VehicleParams>& declaration();
  static Eigen::Matrix<double, 2, 4> defaultRotorPositions(double arm_length);

  // [collective thrust; torque x; torque y; torque z] = effectiveness() * rotor thrusts.
  Mat44 effectiveness() const;
  Mat3 inertia() const { return inertia_diag.asDiagonal(); }
  double hoverThrustPerRotor(double gravity) const { return mass * gravity / 4.0; }
  // The rule for a mass these rotors fly, from the file or at run time (PARAMS FIELD_MASS): within
  // the range vehicle.mass declares and liftable under `gravity`. Empty when accepted, else the
  // reason.
  std::string massInvalidReason(double candidate_mass, double gravity) const;
  // load() reads the `vehicle` mapping: arm_length alone also sets the X layout unless rotor_xy is
  // given.
};

}  // namespace sdlqr
