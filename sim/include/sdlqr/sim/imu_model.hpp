#pragma once
// MEMS IMU: gyro = body rate + bias + white noise, accel = specific force R^T (a - g) + bias +
// white noise, with biases that start at a random offset and wander as a random walk. Readings
// clip at the sensor's range, as a real one does during a touchdown.

#include <cstdint>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/sim/random.hpp"
#include "sdlqr/sim/sim_params.hpp"

namespace sdlqr::sim {

class ImuModel {
 public:
  ImuModel(const ImuParams& params, uint64_t seed);

  // One sample at utime from the true body rate [rad/s] and specific force [m/s^2] (both body
  // frame). The biases first walk for one IMU period; gyroBias()/accelBias() are then the ones
  // inside this sample.
  ImuSample sample(int64_t utime, const Vec3& body_rate, const Vec3& specific_force);

  const Vec3& gyroBias() const { return gyro_bias_; }
  const Vec3& accelBias() const { return accel_bias_; }

 private:
  Random random_;
  double gyro_noise_std_;   // per sample: density x sqrt(rate)
  double accel_noise_std_;
  double gyro_walk_std_;    // per sample: random walk x sqrt(period)
  double accel_walk_std_;
  double gyro_range_;
  double accel_range_;
  Vec3 gyro_bias_;
  Vec3 accel_bias_;
  int64_t seq_ = 0;
};

}  // namespace sdlqr::sim
