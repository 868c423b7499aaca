#include "sdlqr/math/vehicle.hpp"

#include <cmath>

#include <Eigen/LU>

#include "sdlqr/math/model.hpp"

namespace sdlqr {

Eigen::Matrix<double, 2, 4> VehicleParams::defaultRotorPositions(double arm_length) {
  const double d = arm_length / std::sqrt(2.0);
  Eigen::Matrix<double, 2, 4> xy;
  xy << d, -d, d, -d,
        -d, d, d, -d;
  return xy;
}

Mat44 VehicleParams::effectiveness() const {
  Mat44 e;
  for (int i = 0; i < 4; ++i) {
    e(0, i) = 1.0;
    e(1, i) = rotor_xy(1, i);                        // tau_x = y T
    e(2, i) = -rotor_xy(0, i);                       // tau_y = -x T
    e(3, i) = yaw_sign[i] * torque_coefficient;      // tau_z from rotor drag
  }
  return e;
}

VehicleParams VehicleParams::load(const ConfigReader& vehicle) {
  vehicle.allowOnly({"mass", "inertia_diag", "arm_length", "max_rotor_thrust", "min_rotor_thrust",
                     "torque_coefficient", "motor_time_constant", "rotor_drag", "rotor_xy", "yaw_sign"});
  VehicleParams p;
  vehicle.read("mass", p.mass);
  vehicle.read("inertia_diag", p.inertia_diag);
  vehicle.read("arm_length", p.arm_length);
  p.rotor_xy = defaultRotorPositions(p.arm_length);
  vehicle.read("max_rotor_thrust", p.max_rotor_thrust);
  vehicle.read("min_rotor_thrust", p.min_rotor_thrust);
  vehicle.read("torque_coefficient", p.torque_coefficient);
  vehicle.read("motor_time_constant", p.motor_time_constant);
  vehicle.read("rotor_drag", p.rotor_drag);
  if (vehicle.has("rotor_xy")) {
    Eigen::Matrix<double, 8, 1> flat;
    vehicle.read("rotor_xy", flat);  // x0, y0, x1, y1, ...
    for (int i = 0; i < 4; ++i) p.rotor_xy.col(i) << flat[2 * i], flat[2 * i + 1];
  }
  vehicle.read("yaw_sign", p.yaw_sign);
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(vehicle.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string VehicleParams::invalidReason() const {
  if (!(mass > 0.0 && mass < 100.0)) return "mass: must be in (0, 100) kg";
  for (int i = 0; i < 3; ++i) {
    if (!(inertia_diag[i] > 0.0)) return "inertia_diag: every moment must be > 0";
  }
  // Principal moments of a rigid body satisfy the triangle inequality.
  if (inertia_diag[0] + inertia_diag[1] < inertia_diag[2] || inertia_diag[1] + inertia_diag[2] < inertia_diag[0] ||
      inertia_diag[0] + inertia_diag[2] < inertia_diag[1]) {
    return "inertia_diag: violates the triangle inequality of principal moments";
  }
  if (!(arm_length > 0.0)) return "arm_length: must be > 0";
  if (!(min_rotor_thrust >= 0.0)) return "min_rotor_thrust: must be >= 0";
  if (!(max_rotor_thrust > min_rotor_thrust)) return "max_rotor_thrust: must be > min_rotor_thrust";
  if (!(4.0 * max_rotor_thrust > mass * kDefaultGravity)) return "max_rotor_thrust: cannot lift the mass";
  if (!(torque_coefficient > 0.0)) return "torque_coefficient: must be > 0";
  if (!(motor_time_constant >= 0.0 && motor_time_constant < 1.0)) return "motor_time_constant: must be in [0, 1) s";
  for (int i = 0; i < 3; ++i) {
    if (!(rotor_drag[i] >= 0.0)) return "rotor_drag: every coefficient must be >= 0";
  }
  for (int i = 0; i < 4; ++i) {
    if (std::abs(std::abs(yaw_sign[i]) - 1.0) > 0.0) return "yaw_sign: entries must be +1 or -1";
  }
  if (std::abs(yaw_sign.sum()) > 0.0) return "yaw_sign: needs two +1 and two -1";
  // The layout must give full authority in thrust and all three torques.
  Eigen::FullPivLU<Mat44> lu(effectiveness());
  if (lu.rank() < 4) return "rotor_xy: rotor layout cannot produce every torque";
  return {};
}

}  // namespace sdlqr
