#include "sdlqr/controller/geometric_control.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::controller {

namespace {

Vec3 vee(const Mat3& m) { return Vec3(m(2, 1), m(0, 2), m(1, 0)); }

// The rotation whose z axis is z_d and whose x axis points along the heading `yaw` as far as z_d allows.
Mat3 desiredRotation(const Vec3& z_d, double yaw) {
  const Vec3 heading(std::cos(yaw), std::sin(yaw), 0.0);
  Vec3 y_d = z_d.cross(heading);
  // z_d along the heading (a 90 degree pitch): any y orthogonal to z_d will do.
  if (y_d.norm() < 1e-6) y_d = z_d.cross(Vec3::UnitZ().cross(z_d).norm() > 1e-6 ? Vec3::UnitZ() : Vec3::UnitY());
  y_d.normalize();
  Mat3 R;
  R.col(0) = y_d.cross(z_d);
  R.col(1) = y_d;
  R.col(2) = z_d;
  return R;
}

}  // namespace

ControlOutput geometricControl(const State& x, const State& x_ref, const Input& u_ref, const GeometricGains& gains,
                               const LqrParams& limits, const ErrorBounds& bounds) {
  const State error = stateError(x, x_ref, orientation(x_ref), bounds);
  const Vec3 gravity(0.0, 0.0, limits.gravity);
  const Vec3 reference_acceleration = quat::rotate(orientation(x_ref), Vec3(0.0, 0.0, u_ref[kThrust])) - gravity;
  Vec3 a_des = reference_acceleration - gains.position.cwiseProduct(position(error)) -
               gains.velocity.cwiseProduct(velocity(error)) + gravity;
  a_des[2] = std::max(a_des[2], gains.min_vertical_acceleration);

  const Mat3 R = quat::rotationMatrix(orientation(x));
  const Mat3 R_des = desiredRotation(a_des.normalized(), quat::yaw(orientation(x_ref)));
  const Vec3 e_R = 0.5 * vee(R_des.transpose() * R - R.transpose() * R_des);

  const Vec3 omega = R.transpose() * R_des * bodyRate(u_ref) - gains.attitude.cwiseProduct(e_R);
  return applyInputLimits(makeInput(omega, a_des.dot(R.col(2))), limits);
}

}  // namespace sdlqr::controller
