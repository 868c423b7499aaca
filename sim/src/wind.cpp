#include "sdlqr/sim/wind.hpp"

#include <cmath>

namespace sdlqr::sim {

namespace {
constexpr uint64_t kWindStream = 4;  // after the IMU (1) and VIO (2, 3) streams
}  // namespace

Wind::Wind(const WindParams& params, double dt, uint64_t seed)
    : params_(params),
      random_(seed, kWindStream),
      decay_(std::exp(-dt / params.gust_time_constant)),
      drive_(std::sqrt(1.0 - decay_ * decay_)) {
  for (int i = 0; i < 3; ++i) gust_[i] = params_.gust_std[i] * random_.normal();
}

void Wind::advance() {
  for (int i = 0; i < 3; ++i) gust_[i] = decay_ * gust_[i] + params_.gust_std[i] * drive_ * random_.normal();
}

}  // namespace sdlqr::sim
