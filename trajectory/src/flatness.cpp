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

namespace {

// The body frame whose z axis carries `thrust_vector` at heading `yaw` (the header's construction).
struct BodyFrame {
  Mat3 rotation;
  double thrust = 0.0;
  bool singular = false;
};

BodyFrame frameOf(const Vec3& thrust_vector, double yaw) {
  BodyFrame frame;
  frame.thrust = thrust_vector.norm();
  const double c = frame.thrust;
  const Vec3 y_c(-std::sin(yaw), std::cos(yaw), 0.0);
  Vec3 z_b = Vec3::UnitZ();
  if (c > kMinThrust) z_b = thrust_vector / c;
  Vec3 x_b_unnormalized = y_c.cross(z_b);
  frame.singular = c <= kMinThrust || x_b_unnormalized.norm() < kMinHeadingSine;
  if (frame.singular) {
    z_b = Vec3::UnitZ();
    x_b_unnormalized = y_c.cross(z_b);
  }
  const Vec3 x_b = x_b_unnormalized.normalized();
  const Vec3 y_b = z_b.cross(x_b);
  frame.rotation << x_b, y_b, z_b;
  return frame;
}

// Body rates of `frame` while its thrust vector changes at `thrust_vector_rate` and the heading at
// yaw_rate; zero where the frame is singular.
Vec3 bodyRatesOf(const BodyFrame& frame, const Vec3& thrust_vector_rate, double yaw, double yaw_rate) {
  Vec3 omega = Vec3::Zero();
  if (frame.singular) return omega;
  const Vec3 x_c(std::cos(yaw), std::sin(yaw), 0.0);
  const Vec3 y_c(-std::sin(yaw), std::cos(yaw), 0.0);
  const Vec3 x_b = frame.rotation.col(0), y_b = frame.rotation.col(1), z_b = frame.rotation.col(2);
  const Vec3 z_b_rate = (thrust_vector_rate - z_b.dot(thrust_vector_rate) * z_b) / frame.thrust;
  omega.x() = -z_b_rate.dot(y_b);
  omega.y() = z_b_rate.dot(x_b);
  omega.z() = (yaw_rate * x_b.dot(x_c) + omega.y() * z_b.dot(y_c)) / y_b.dot(y_c);
  return omega;
}

FlatReference referenceOf(const FlatOutput& flat, const BodyFrame& frame, const Vec3& omega) {
  FlatReference ref;
  ref.singular = frame.singular;
  ref.x = makeState(flat.position, quaternionFromRotation(frame.rotation), flat.velocity);
  ref.u = makeInput(omega, frame.thrust);
  return ref;
}

constexpr int kDragIterations = 50;       // fixed-point steps at most (each contracts by ~drag / thrust)
constexpr double kDragTolerance = 1e-12;  // [m/s^2] change of the thrust vector that ends them
constexpr int kDragRateIterations = 8;    // the rates' fixed point (omega and c' appear on both sides)

// d/dt of s R D R^T v along the reference: s' c' R D R^T v + s (R (W D - D W) R^T v + R D R^T a),
// W = [omega]x.
Vec3 dragRate(const Mat3& r, const Vec3& omega, double thrust, double thrust_rate, const FlatOutput& flat,
              const RotorDrag& drag) {
  const Mat3 d = drag.coefficients.asDiagonal();
  Mat3 w;
  w << 0.0, -omega.z(), omega.y(), omega.z(), 0.0, -omega.x(), -omega.y(), omega.x(), 0.0;
  const Vec3 v_body = r.transpose() * flat.velocity;
  const double s = drag.rotorSpeedRatio(thrust);
  return drag.rotorSpeedRatioSlope(thrust) * thrust_rate * (r * (d * v_body)) +
         s * (r * ((w * d - d * w) * v_body) + r * (d * (r.transpose() * flat.acceleration)));
}

}  // namespace

FlatReference flatToReference(const FlatOutput& flat, double gravity) {
  const Vec3 thrust_vector = flat.acceleration + Vec3(0.0, 0.0, gravity);
  const BodyFrame frame = frameOf(thrust_vector, flat.yaw);
  return referenceOf(flat, frame, bodyRatesOf(frame, flat.jerk, flat.yaw, flat.yaw_rate));
}

FlatReference flatToReference(const FlatOutput& flat, double gravity, const RotorDrag& drag) {
  if (!drag.active()) return flatToReference(flat, gravity);
  const Vec3 drag_free = flat.acceleration + Vec3(0.0, 0.0, gravity);
  BodyFrame frame = frameOf(drag_free, flat.yaw);
  Vec3 thrust_vector = drag_free;
  for (int k = 0; k < kDragIterations && !frame.singular; ++k) {
    const Quat q = quaternionFromRotation(frame.rotation);
    const Vec3 next = drag_free - rotorDragAcceleration(q, flat.velocity, frame.thrust, drag);
    const bool settled = (next - thrust_vector).norm() < kDragTolerance;
    thrust_vector = next;
    frame = frameOf(thrust_vector, flat.yaw);
    if (settled) break;
  }
  Vec3 omega = bodyRatesOf(frame, flat.jerk, flat.yaw, flat.yaw_rate);
  double thrust_rate = frame.rotation.col(2).dot(flat.jerk);
  for (int k = 0; k < kDragRateIterations && !frame.singular; ++k) {
    const Vec3 rate = flat.jerk + dragRate(frame.rotation, omega, frame.thrust, thrust_rate, flat, drag);
    omega = bodyRatesOf(frame, rate, flat.yaw, flat.yaw_rate);
    thrust_rate = frame.rotation.col(2).dot(rate);
  }
  return referenceOf(flat, frame, omega);
}

}  // namespace sdlqr::trajectory
