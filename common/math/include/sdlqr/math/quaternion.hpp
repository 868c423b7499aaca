#pragma once
// Hamilton quaternions stored (w, x, y, z) as in the paper, eq. (4)-(9).
// Header-only: every function is small and used in the 1 kHz and 100 Hz loops.

#include <algorithm>
#include <cmath>

#include "sdlqr/math/types.hpp"

namespace sdlqr::quat {

// Q^x(q) of eq. (6): q (x) p = leftMatrix(q) p.
inline Mat4 leftMatrix(const Quat& q) {
  Mat4 m;
  m << q[0], -q[1], -q[2], -q[3],
       q[1],  q[0], -q[3],  q[2],
       q[2],  q[3],  q[0], -q[1],
       q[3], -q[2],  q[1],  q[0];
  return m;
}

// Qbar^x(p) of eq. (7): q (x) p = rightMatrix(p) q.
inline Mat4 rightMatrix(const Quat& p) {
  Mat4 m;
  m << p[0], -p[1], -p[2], -p[3],
       p[1],  p[0],  p[3], -p[2],
       p[2], -p[3],  p[0],  p[1],
       p[3],  p[2], -p[1],  p[0];
  return m;
}

inline Quat multiply(const Quat& a, const Quat& b) {
  return Quat(a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
              a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
              a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
              a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]);
}

inline Quat conjugate(const Quat& q) { return Quat(q[0], -q[1], -q[2], -q[3]); }

inline Quat pure(const Vec3& v) { return Quat(0.0, v[0], v[1], v[2]); }

// Rotation matrix R^x(q) of eq. (5) for a unit quaternion, body to world.
inline Mat3 rotationMatrix(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Mat3 r;
  r << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
       2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return r;
}

inline Vec3 rotate(const Quat& q, const Vec3& v) { return rotationMatrix(q) * v; }
inline Vec3 rotateInverse(const Quat& q, const Vec3& v) { return rotationMatrix(q).transpose() * v; }

// Third column of R(q): the body z (thrust) axis in world coordinates, eq. (10).
inline Vec3 bodyZ(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return Vec3(2 * (w * y + x * z), 2 * (y * z - w * x), w * w - x * x - y * y + z * z);
}

// Unit quaternion for a rotation vector (axis * angle), exact for any angle.
inline Quat exp(const Vec3& rotation_vector) {
  const double angle = rotation_vector.norm();
  if (angle < 1e-8) {
    // Second-order series keeps the result unit to machine precision near zero.
    const Vec3 h = 0.5 * rotation_vector;
    Quat q(1.0 - 0.5 * h.squaredNorm(), h[0], h[1], h[2]);
    return q.normalized();
  }
  const double s = std::sin(0.5 * angle) / angle;
  return Quat(std::cos(0.5 * angle), s * rotation_vector[0], s * rotation_vector[1], s * rotation_vector[2]);
}

// Rotation vector of a unit quaternion, angle in [0, pi] (q and -q give the same result).
inline Vec3 log(const Quat& q_in) {
  const Quat q = q_in[0] < 0.0 ? Quat(-q_in) : q_in;
  const Vec3 v = q.tail<3>();
  const double s = v.norm();
  if (s < 1e-12) return 2.0 * v;
  return (2.0 * std::atan2(s, q[0]) / s) * v;
}

// Rotation about world z by yaw.
inline Quat fromYaw(double yaw) { return Quat(std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw)); }

// Heading of the body x axis projected on the world x-y plane.
inline double yaw(const Quat& q) {
  return std::atan2(2.0 * (q[0] * q[3] + q[1] * q[2]), 1.0 - 2.0 * (q[2] * q[2] + q[3] * q[3]));
}

// Angle between body z and world z: 0 level, pi upside down.
inline double tilt(const Quat& q) {
  const double cz = std::clamp(bodyZ(q.normalized())[2], -1.0, 1.0);
  return std::acos(cz);
}

// q or -q, whichever lies in the hemisphere of `reference` (both encode the same rotation).
inline Quat sameHemisphere(const Quat& q, const Quat& reference) { return q.dot(reference) < 0.0 ? Quat(-q) : q; }

// Rotation from a to b as a rotation vector in the frame of a: log(conj(a) (x) b).
inline Vec3 boxMinus(const Quat& b, const Quat& a) { return log(multiply(conjugate(a), b)); }

}  // namespace sdlqr::quat
