#pragma once
// First-order low-pass filter with a cutoff frequency, discretized per sample so that a
// jittery dt (taken from IMU timestamps) keeps the intended time constant.

#include <cmath>

namespace sdlqr::lowlevel {

// Weight of a new sample for a first-order low-pass of cutoff `cutoff_hz` after `dt` seconds.
inline double lowPassAlpha(double cutoff_hz, double dt) {
  const double time_constant = 1.0 / (2.0 * M_PI * cutoff_hz);
  return dt / (dt + time_constant);
}

// The same for a filter given by its time constant (0 passes the input through).
inline double lagAlpha(double time_constant, double dt) { return time_constant > 0.0 ? dt / (dt + time_constant) : 1.0; }

template <typename T>
class LowPass {
 public:
  explicit LowPass(T initial) : value_(initial) {}
  const T& update(const T& sample, double alpha) {
    value_ += alpha * (sample - value_);
    return value_;
  }
  void reset(const T& value) { value_ = value; }
  const T& value() const { return value_; }

 private:
  T value_;
};

}  // namespace sdlqr::lowlevel
