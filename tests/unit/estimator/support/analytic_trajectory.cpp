#include "analytic_trajectory.hpp"

#include <cmath>

#include <Eigen/Geometry>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator::test {

namespace {

// Septic smoothstep and its first two derivatives with respect to u in [0, 1]: value 0 -> 1 with
// derivatives up to the third zero at both ends.
struct Envelope {
  double e, de, dde;
};
Envelope envelope(double t, double ramp) {
  if (t <= 0.0) return {0.0, 0.0, 0.0};
  if (t >= ramp) return {1.0, 0.0, 0.0};
  const double u = t / ramp;
  const double u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u, u6 = u5 * u, u7 = u6 * u;
  const double e = 35 * u4 - 84 * u5 + 70 * u6 - 20 * u7;
  const double de = (140 * u3 - 420 * u4 + 420 * u5 - 140 * u6) / ramp;
  const double dde = (420 * u2 - 1680 * u3 + 2100 * u4 - 840 * u5) / (ramp * ramp);
  return {e, de, dde};
}

}  // namespace

TrajectorySpec TrajectorySpec::hover(const Vec3& center, double yaw) {
  TrajectorySpec spec;
  spec.center = center;
  spec.yaw = yaw;
  spec.amplitude.setZero();
  spec.yaw_amplitude = 0.0;
  return spec;
}

AnalyticTrajectory::Kinematics AnalyticTrajectory::kinematics(double t) const {
  const double tau = t - spec_.hover_time;
  const Envelope env = envelope(tau, spec_.ramp_time);
  const double w = 2.0 * M_PI / spec_.period;
  const double phase = tau > 0.0 ? w * tau : 0.0;
  const Vec3& amp = spec_.amplitude;
  // Shape s(tau) and its derivatives.
  const Vec3 s(amp.x() * std::sin(phase), amp.y() * std::sin(2.0 * phase), amp.z() * std::sin(phase));
  const Vec3 ds = tau > 0.0 ? Vec3(amp.x() * w * std::cos(phase), amp.y() * 2.0 * w * std::cos(2.0 * phase),
                                   amp.z() * w * std::cos(phase))
                            : Vec3::Zero();
  const Vec3 dds = tau > 0.0 ? Vec3(-amp.x() * w * w * std::sin(phase), -amp.y() * 4.0 * w * w * std::sin(2.0 * phase),
                                    -amp.z() * w * w * std::sin(phase))
                             : Vec3::Zero();
  Kinematics k;
  k.p = spec_.center + env.e * s;
  k.v = env.de * s + env.e * ds;
  k.a = env.dde * s + 2.0 * env.de * ds + env.e * dds;
  k.yaw = spec_.yaw + env.e * spec_.yaw_amplitude * std::sin(phase);
  return k;
}

Quat AnalyticTrajectory::attitude(const Kinematics& k) const {
  const Vec3 thrust = k.a + Vec3(0.0, 0.0, spec_.gravity);
  const Vec3 z_body = thrust.normalized();
  const Vec3 heading(std::cos(k.yaw), std::sin(k.yaw), 0.0);
  const Vec3 y_body = z_body.cross(heading).normalized();
  const Vec3 x_body = y_body.cross(z_body);
  Mat3 r;
  r << x_body, y_body, z_body;
  const Eigen::Quaterniond q(r);
  return Quat(q.w(), q.x(), q.y(), q.z());
}

TruthSample AnalyticTrajectory::at(double t) const {
  const Kinematics k = kinematics(t);
  TruthSample out;
  out.position = k.p;
  out.velocity = k.v;
  out.acceleration = k.a;
  out.orientation = attitude(k);
  // Body rate by a central difference of the attitude: the error, O(h^2) ~ 1e-8 rad/s, is far
  // below any sensor noise, and it avoids hand-deriving the rate of a thrust-aligned frame.
  const double h = 1e-4;
  const Quat before = attitude(kinematics(t - h));
  const Quat after = attitude(kinematics(t + h));
  out.body_rate = quat::boxMinus(after, before) / (2.0 * h);
  out.specific_force = quat::rotateInverse(out.orientation, k.a + Vec3(0.0, 0.0, spec_.gravity));
  return out;
}

}  // namespace sdlqr::estimator::test
