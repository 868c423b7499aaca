#include "sdlqr/estimator/imu_downsampler.hpp"

#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator {

namespace {

int64_t floorDiv(int64_t a, int64_t b) { return a / b - ((a % b != 0) && ((a < 0) != (b < 0)) ? 1 : 0); }

}  // namespace

void ImuDownsampler::start(const ImuSample& sample) {
  started_ = true;
  previous_ = sample;
  window_end_ = (floorDiv(sample.utime, period_us_) + 1) * period_us_;
  turn_ = identityQuat();
  window_.delta = ImuDelta();
}

void ImuDownsampler::accumulate(const ImuSample& sample, int64_t from, int64_t to) {
  const double span = static_cast<double>(sample.utime - previous_.utime);
  const double a = static_cast<double>(from - previous_.utime) / span;
  const double b = static_cast<double>(to - previous_.utime) / span;
  // Mean of the linearly interpolated reading over [from, to].
  const double mid = 0.5 * (a + b);
  const Vec3 rate = previous_.gyro + mid * (sample.gyro - previous_.gyro);
  const Vec3 force = previous_.accel + mid * (sample.accel - previous_.accel);
  const double h = static_cast<double>(to - from) * 1e-6;

  // Specific force rotated into the window-start frame at the middle of the step (sculling to
  // first order), then the step's rotation appended (coning to first order).
  const Quat half_turn = quat::multiply(turn_, quat::exp(0.5 * h * rate));
  window_.delta.delta_velocity += quat::rotate(half_turn, force * h);
  turn_ = quat::multiply(turn_, quat::exp(h * rate)).normalized();
  window_.delta.dt += h;
}

void ImuDownsampler::countClipping(const ImuSample& sample) {
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(sample.accel[axis]) >= accel_clip_level_) window_.delta.accel_clipped[axis] += 1.0;
  }
}

const ImuWindow& ImuDownsampler::closeWindow(int64_t seq) {
  window_.end_utime = window_end_;
  window_.last_imu_seq = seq;
  window_.delta.delta_angle = quat::log(turn_);
  // Leave the finished window readable by the caller; the next one restarts from here.
  closed_ = window_;
  window_end_ += period_us_;
  turn_ = identityQuat();
  window_.delta = ImuDelta();
  return closed_;
}

}  // namespace sdlqr::estimator
