#include "sdlqr/math/vehicle.hpp"

#include <cmath>

#include <Eigen/LU>

#include "sdlqr/math/model.hpp"

#include "vehicle_rows.hpp"

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

VehicleParams::VehicleParams() { declaration().setDefaults(*this); }

std::string VehicleParams::massInvalidReason(double candidate_mass, double gravity) const {
  const Range& range = declaration().info("mass").range;
  if (!range.contains(candidate_mass)) return range.rule("kg");
  if (!(4.0 * max_rotor_thrust > candidate_mass * gravity)) return "the rotors cannot lift it";
  return {};
}

namespace {

// rotor_xy's derive, get and set (its row in params/vehicle.yaml names them).
using FlatRotors = Eigen::Matrix<double, 8, 1>;  // x0, y0, x1, y1, ...

FlatRotors flatRotors(const VehicleParams& p) { return Eigen::Map<const FlatRotors>(p.rotor_xy.data()); }
void setRotors(VehicleParams& p, const FlatRotors& flat) { p.rotor_xy = Eigen::Map<const Eigen::Matrix<double, 2, 4>>(flat.data()); }
void xLayout(VehicleParams& p) { p.rotor_xy = VehicleParams::defaultRotorPositions(p.arm_length); }

bool triangleInequality(const Vec3& j) { return j[0] + j[1] >= j[2] && j[1] + j[2] >= j[0] && j[0] + j[2] >= j[1]; }

}  // namespace

const ParamTable<VehicleParams>& VehicleParams::declaration() {
  static const ParamTable<VehicleParams> table = [] {
    using P = VehicleParams;
    ParamTable<P> t = vehicleParamsRows();
    // Principal moments of a rigid body satisfy the triangle inequality.
    t.check("inertia_diag", [](const P& p) { return triangleInequality(p.inertia_diag); },
            "violates the triangle inequality of principal moments");
    t.check("max_rotor_thrust", [](const P& p) { return p.max_rotor_thrust > p.min_rotor_thrust; },
            "must be > min_rotor_thrust");
    t.check("max_rotor_thrust", [](const P& p) { return p.massInvalidReason(p.mass, kDefaultGravity).empty(); },
            "cannot lift the mass");
    t.check("yaw_sign", [](const P& p) { return (p.yaw_sign.array().abs() == 1.0).all(); }, "entries must be +1 or -1");
    t.check("yaw_sign", [](const P& p) { return p.yaw_sign.sum() == 0.0; }, "needs two +1 and two -1");
    // The layout must give full authority in thrust and all three torques.
    t.check("rotor_xy", [](const P& p) { return Eigen::FullPivLU<Mat44>(p.effectiveness()).rank() == 4; },
            "rotor layout cannot produce every torque");
    return t;
  }();
  return table;
}

}  // namespace sdlqr
