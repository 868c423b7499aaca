#include "sdlqr/sim/imu_model.hpp"

#include <cmath>

namespace sdlqr::sim {

namespace {
constexpr uint64_t kImuStream = 1;
}

ImuModel::ImuModel(const ImuParams& params, uint64_t seed)
    : random_(seed, kImuStream),
      gyro_noise_std_(params.gyro_noise_density * std::sqrt(static_cast<double>(params.rate_hz))),
      accel_noise_std_(params.accel_noise_density * std::sqrt(static_cast<double>(params.rate_hz))),
      gyro_walk_std_(params.gyro_bias_random_walk / std::sqrt(static_cast<double>(params.rate_hz))),
      accel_walk_std_(params.accel_bias_random_walk / std::sqrt(static_cast<double>(params.rate_hz))),
      gyro_range_(params.gyro_range),
      accel_range_(params.accel_range) {
  gyro_bias_ = random_.uniform3(params.gyro_bias_initial_max);
  accel_bias_ = random_.uniform3(params.accel_bias_initial_max);
}

ImuSample ImuModel::sample(int64_t utime, const Vec3& body_rate, const Vec3& specific_force) {
  gyro_bias_ += random_.normal3(gyro_walk_std_);
  accel_bias_ += random_.normal3(accel_walk_std_);
  ImuSample s;
  s.utime = utime;
  s.seq = seq_++;
  s.gyro = (body_rate + gyro_bias_ + random_.normal3(gyro_noise_std_)).cwiseMax(-gyro_range_).cwiseMin(gyro_range_);
  s.accel = (specific_force + accel_bias_ + random_.normal3(accel_noise_std_))
                .cwiseMax(-accel_range_)
                .cwiseMin(accel_range_);
  return s;
}

}  // namespace sdlqr::sim
