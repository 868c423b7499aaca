#pragma once
// The air's velocity at the vehicle: steady wind plus turbulence. Per world axis the gust is a
// first-order Gauss-Markov process g' = -g / tau + noise, sampled exactly on the physics grid
// (g_k+1 = a g_k + std sqrt(1 - a^2) n_k, a = exp(-dt / tau)), so its std is gust_std at any
// physics rate; it starts from the stationary distribution. Its own random stream of the
// simulator's seed: a seed repeats the wind, and the sensor noise stays what it was.

#include <cstdint>

#include "sdlqr/sim/random.hpp"
#include "sdlqr/sim/stress_params.hpp"

namespace sdlqr::sim {

class Wind {
 public:
  Wind(const WindParams& params, double dt, uint64_t seed);

  // Moves the turbulence one physics step on.
  void advance();
  // [m/s] world, constant over a physics step.
  Vec3 velocity() const { return params_.steady + gust_; }
  bool enabled() const { return params_.enabled(); }

 private:
  WindParams params_;
  Random random_;
  double decay_;  // a
  double drive_;  // sqrt(1 - a^2)
  Vec3 gust_ = Vec3::Zero();
};

// Quadratic drag of the frame in the relative wind [N, world]: -c |v - w| (v - w).
inline Vec3 frameDrag(double coefficient, const Vec3& velocity, const Vec3& wind) {
  const Vec3 relative = velocity - wind;
  return -coefficient * relative.norm() * relative;
}

}  // namespace sdlqr::sim
