#include "sdlqr/math/model.hpp"

#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr {

namespace {

// d(column i of R(q)) / dq for a unit q = (w, x, y, z), R written homogeneously (quadratic) in q.
Eigen::Matrix<double, 3, 4> rotationColumnJacobian(const Quat& q, int column) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Eigen::Matrix<double, 3, 4> d;
  if (column == 0) {
    d << w, x, -y, -z,
         z, y, x, w,
         -y, z, -w, x;
  } else if (column == 1) {
    d << -z, y, x, -w,
         w, -x, y, -z,
         x, w, z, y;
  } else {
    d << y, z, w, x,
         -x, -w, z, y,
         w, -x, -y, z;
  }
  return 2.0 * d;
}

// The drag's terms of A and B (added to the paper's): A_vv = -s R D R^T, A_vq = -s d(R D R^T v)/dq_u P,
// B_vc = -theta s'(c) R D R^T v.
void addRotorDragJacobians(const Quat& q_unit, const Mat4& projection, const Vec3& v, double c, double thrust_gain,
                           const RotorDrag& drag, Linearization& lin) {
  const Mat3 r = quat::rotationMatrix(q_unit);
  const Mat3 rdr = r * drag.coefficients.asDiagonal() * r.transpose();
  const double s = drag.rotorSpeedRatio(c);
  Eigen::Matrix<double, 3, 4> d_rdrv = Eigen::Matrix<double, 3, 4>::Zero();
  for (int i = 0; i < 3; ++i) {
    const Vec3 column = r.col(i);
    const Mat3 weight = column.dot(v) * Mat3::Identity() + column * v.transpose();
    d_rdrv += drag.coefficients[i] * weight * rotationColumnJacobian(q_unit, i);
  }
  lin.A.block<3, 3>(kVel, kVel) -= s * rdr;
  lin.A.block<3, 4>(kVel, kQuat) -= s * d_rdrv * projection;
  lin.B.block<3, 1>(kVel, kThrust) -= thrust_gain * drag.rotorSpeedRatioSlope(c) * (rdr * v);
}

}  // namespace

double RotorDrag::rotorSpeedRatio(double thrust) const { return thrust > 0.0 ? std::sqrt(thrust / gravity) : 0.0; }

double RotorDrag::rotorSpeedRatioSlope(double thrust) const {
  return thrust > 0.0 ? 0.5 / std::sqrt(thrust * gravity) : 0.0;
}

Vec3 rotorDragAcceleration(const Quat& q_unit, const Vec3& velocity, double thrust, const RotorDrag& drag) {
  const Mat3 r = quat::rotationMatrix(q_unit);
  return -drag.rotorSpeedRatio(thrust) * (r * drag.coefficients.cwiseProduct(r.transpose() * velocity));
}

State dynamics(const State& x, const Input& u, double gravity, const RotorDrag& drag) {
  const Quat q_unit = orientation(x).normalized();
  const double thrust = u[kThrust];

  State x_dot;
  position(x_dot) = velocity(x);
  orientation(x_dot) = 0.5 * quat::multiply(q_unit, quat::pure(bodyRate(u)));
  velocity(x_dot) = thrust * quat::bodyZ(q_unit) - Vec3(0.0, 0.0, gravity);
  if (drag.active()) velocity(x_dot) += rotorDragAcceleration(q_unit, velocity(x), thrust, drag);
  return x_dot;
}

Mat4 unitProjectionJacobian(const Quat& q) {
  const double norm_sq = q.squaredNorm();
  const double norm = std::sqrt(norm_sq);
  return (Mat4::Identity() - q * q.transpose() / norm_sq) / norm;
}

Linearization linearize(const State& x, const Input& u, double thrust_gain, const RotorDrag& drag) {
  const Quat q = orientation(x);
  const Quat q_unit = q.normalized();
  const Mat4 projection = unitProjectionJacobian(q);
  const double w = q_unit[0], qx = q_unit[1], qy = q_unit[2], qz = q_unit[3];
  const double c = u[kThrust];

  Linearization lin;
  lin.A.setZero();
  lin.B.setZero();

  // eq. (19)
  lin.A.block<3, 3>(kPos, kVel).setIdentity();

  // eq. (20): q_dot = 1/2 Qbar([0, omega]) q_u
  lin.A.block<4, 4>(kQuat, kQuat) = 0.5 * quat::rightMatrix(quat::pure(bodyRate(u))) * projection;

  // eq. (22), derivative of c * bodyZ(q_u); bodyZ is written homogeneously in q_u.
  Eigen::Matrix<double, 3, 4> d_body_z;
  d_body_z << qy, qz, w, qx,
              -qx, -w, qz, qy,
              w, -qx, -qy, qz;
  lin.A.block<3, 4>(kVel, kQuat) = 2.0 * c * d_body_z * projection;

  // eq. (21), corrected: the last three columns of Q^x(q_u), halved.
  lin.B.block<4, 3>(kQuat, kRate) = 0.5 * quat::leftMatrix(q_unit).rightCols<3>();

  // eq. (23), corrected: the first two rows carry a factor 2.
  lin.B.block<3, 1>(kVel, kThrust) = thrust_gain * quat::bodyZ(q_unit);
  if (drag.active()) addRotorDragJacobians(q_unit, projection, velocity(x), c, thrust_gain, drag, lin);
  return lin;
}

}  // namespace sdlqr
