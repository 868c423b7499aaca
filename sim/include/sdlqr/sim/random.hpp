#pragma once
// A small random source whose sequence is fixed by this file alone (xoshiro256** seeded by
// splitmix64, Box-Muller normals), so a seed reproduces a flight bit for bit whatever standard
// library the simulator is built with — std::normal_distribution gives no such promise.

#include <cmath>
#include <cstdint>

#include "sdlqr/math/types.hpp"

namespace sdlqr::sim {

class Random {
 public:
  // `stream` separates independent sources drawn from one seed (IMU noise, VIO noise, ...), so
  // changing how much one of them draws leaves the others untouched.
  Random(uint64_t seed, uint64_t stream) {
    uint64_t mix = seed ^ (0x9E3779B97F4A7C15ULL * (stream + 1));
    for (uint64_t& word : state_) word = splitMix64(mix);
  }

  uint64_t next() {
    const uint64_t result = rotl(state_[1] * 5, 7) * 9;
    const uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotl(state_[3], 45);
    return result;
  }

  // Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }

  // Standard normal; Box-Muller, the second value of each pair kept for the next call.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log stays finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    const double angle = 2.0 * M_PI * u2;
    spare_ = radius * std::sin(angle);
    has_spare_ = true;
    return radius * std::cos(angle);
  }

  // One draw per axis in x, y, z order (argument evaluation order is unspecified, so no Vec3(f(), f(), f())).
  Vec3 normal3(double std_dev) {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = std_dev * normal();
    return v;
  }
  Vec3 uniform3(double half_width) {
    Vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = uniform(-half_width, half_width);
    return v;
  }

 private:
  static uint64_t rotl(uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  static uint64_t splitMix64(uint64_t& x) {
    uint64_t z = (x += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
  }

  uint64_t state_[4];
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace sdlqr::sim
