#include "sdlqr/trajectory/flatness.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace sdlqr::trajectory {

namespace {
// Below these the map is ill-conditioned: thrust [m/s^2] and |y_c x z_b| (sine of the roll margin).
constexpr double kMinThrust = 1e-6;
constexpr double kMinHeadingSine = 1e-6;
}  // namespace

Quat quaternionFromRotation(const Mat3& rotation) {
  const Eigen::Quaterniond q(rotation);  // Eigen's quaternion is Hamilton, same R(q) as quat::rotationMatrix
  Quat out(q.w(), q.x(), q.y(), q.z());
  out.normalize();
  return out[0] < 0.0 ? Quat(-out) : out;
}

FlatReference flatToReference(const FlatOutput& flat, double gravity) {
  FlatReference ref;
  const Vec3 thrust_vector = flat.acceleration + Vec3(0.0, 0.0, gravity);
  const double c = thrust_vector.norm();
  const Vec3 x_c(std::cos(flat.yaw), std::sin(flat.yaw), 0.0);
  const Vec3 y_c(-std::sin(flat.yaw), std::cos(flat.yaw), 0.0);

  Vec3 z_b = Vec3::UnitZ();
  if (c > kMinThrust) z_b = thrust_vector / c;
  Vec3 x_b_unnormalized = y_c.cross(z_b);
  ref.singular = c <= kMinThrust || x_b_unnormalized.norm() < kMinHeadingSine;
  if (ref.singular) {
    z_b = Vec3::UnitZ();
    x_b_unnormalized = y_c.cross(z_b);
  }
  const Vec3 x_b = x_b_unnormalized.normalized();
  const Vec3 y_b = z_b.cross(x_b);
  Mat3 rotation;
  rotation << x_b, y_b, z_b;

  Vec3 omega = Vec3::Zero();
  if (!ref.singular) {
    const Vec3 z_b_rate = (flat.jerk - z_b.dot(flat.jerk) * z_b) / c;
    omega.x() = -z_b_rate.dot(y_b);
    omega.y() = z_b_rate.dot(x_b);
    omega.z() = (flat.yaw_rate * x_b.dot(x_c) + omega.y() * z_b.dot(y_c)) / y_b.dot(y_c);
  }

  ref.x = makeState(flat.position, quaternionFromRotation(rotation), flat.velocity);
  ref.u = makeInput(omega, c);
  return ref;
}

}  // namespace sdlqr::trajectory
