#pragma once
// The states the paper's extensions add to the model (math/lqr_extensions.hpp), kept by the
// controller from tick to tick: the integral of the position error (sdlqr_integral), the
// collective thrust the motors are believed to produce (sdlqr_actuator), and the model's thrust
// gain (sdlqr_adaptive). Allocation-free.

#include <algorithm>
#include <cmath>

#include "sdlqr/math/types.hpp"

namespace sdlqr::controller {

// xi = integral of (p - p_ref) [m s], with anti-windup: it only integrates while the command was
// not saturated (or when the error shrinks xi), and its norm never exceeds `limit`.
class PositionErrorIntegral {
 public:
  void reset() { xi_.setZero(); }
  void update(const Vec3& position_error, double dt, bool saturated, double limit) {
    const Vec3 next = xi_ + dt * position_error;
    if (saturated && next.norm() > xi_.norm()) return;
    xi_ = next.norm() > limit ? Vec3(next * (limit / next.norm())) : next;
  }
  const Vec3& value() const { return xi_; }

 private:
  Vec3 xi_ = Vec3::Zero();
};

// c [m/s^2]: the commanded thrust through the model's first-order lag, held over each period
// (zero-order hold, as the model is discretized): c <- c_cmd + (c - c_cmd) exp(-dt / tau).
class ThrustLagModel {
 public:
  explicit ThrustLagModel(double initial) : c_(initial) {}
  void reset(double c) { c_ = c; }
  void update(double commanded, double dt, double tau) {
    c_ = tau > 0.0 ? commanded + (c_ - commanded) * std::exp(-dt / tau) : commanded;
  }
  double value() const { return c_; }

 private:
  double c_;
};

// theta: the vehicle's produced over commanded mass-normalized thrust (1 when the vehicle file's
// mass and thrust are right; 1 / 1.2 with 20 % more mass, 1 / 0.85 after dropping 15 % of it) —
// the paper's "time-varying system dynamics" a model can follow. Between two estimates the
// measured vertical acceleration plus gravity, v'_z + g, is theta times the vertical part of the
// thrust commanded (as the thrust model lags it), c z_b,z: the vertical axis alone, so a horizontal
// push (a hand, a gust) is no thrust error. Each interval nudges theta towards that ratio with a
// time constant (slow: VIO corrections and manoeuvres average out), only while the thrust is well
// above zero and the vehicle within 60 degrees of level; theta stays within [min, max]. Reset to 1
// on the ground; the controller adapts only near its reference (thrust_gain_zone).
class ThrustGainEstimate {
 public:
  void reset() { theta_ = 1.0; }
  // One interval of `dt` [s] over which the velocity changed by `velocity_change` [m/s] (world)
  // with body z `body_z` while `thrust` [m/s^2] was commanded.
  void update(const Vec3& velocity_change, double dt, const Vec3& body_z, double thrust, double gravity,
              double time_constant, double min, double max) {
    if (!(dt > 0.0) || !(thrust > 0.25 * gravity) || !(body_z.z() > 0.5)) return;
    const double sample = (velocity_change.z() / dt + gravity) / (thrust * body_z.z());
    if (!std::isfinite(sample)) return;
    theta_ = std::clamp(theta_ + std::min(1.0, dt / time_constant) * (sample - theta_), min, max);
  }
  double value() const { return theta_; }

 private:
  double theta_ = 1.0;
};

}  // namespace sdlqr::controller
