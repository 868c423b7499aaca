#pragma once
// The states the paper's extensions add to the model (math/lqr_extensions.hpp), kept by the
// controller from tick to tick: the integral of the position error (sdlqr_integral) and the
// collective thrust the motors are believed to produce (sdlqr_actuator). Allocation-free.

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

}  // namespace sdlqr::controller
