#include "sdlqr/math/model.hpp"

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr {

State dynamics(const State& x, const Input& u, double gravity) {
  const Quat q_unit = orientation(x).normalized();
  const double thrust = u[kThrust];

  State x_dot;
  position(x_dot) = velocity(x);
  orientation(x_dot) = 0.5 * quat::multiply(q_unit, quat::pure(bodyRate(u)));
  velocity(x_dot) = thrust * quat::bodyZ(q_unit) - Vec3(0.0, 0.0, gravity);
  return x_dot;
}

Mat4 unitProjectionJacobian(const Quat& q) {
  const double norm_sq = q.squaredNorm();
  const double norm = std::sqrt(norm_sq);
  return (Mat4::Identity() - q * q.transpose() / norm_sq) / norm;
}

Linearization linearize(const State& x, const Input& u, double thrust_gain) {
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
  return lin;
}

}  // namespace sdlqr
