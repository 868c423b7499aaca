#pragma once
// Turns IMU samples at any rate (1 kHz from the simulator) into delta angle / delta velocity over
// the fixed windows of the output grid: window k ends at k * period in IMU time. Samples are
// instantaneous readings, so between two samples the rates are interpolated linearly (trapezoid)
// and an interval crossing a window edge is split at the edge; the windows therefore tile IMU time
// exactly and every output lands on the grid whatever the IMU timestamps are.
//
// An accelerometer reading at or beyond the clip level (per axis) is counted in the window that
// holds its timestamp (ImuDelta::accel_clipped): the integrated delta velocity is short there.

#include <algorithm>
#include <cstdint>
#include <limits>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/estimator/nav_state.hpp"

namespace sdlqr::estimator {

struct ImuWindow {
  int64_t end_utime = 0;      // [us] on the grid
  ImuDelta delta;             // the whole window, or from the first sample when the stream starts mid-window
  int64_t last_imu_seq = -1;  // seq of the sample that closed the window
};

class ImuDownsampler {
 public:
  explicit ImuDownsampler(int64_t period_us,
                          double accel_clip_level = std::numeric_limits<double>::infinity())  // [m/s^2]
      : period_us_(period_us), accel_clip_level_(accel_clip_level) {}

  // Forget everything; the next sample starts the stream again.
  void reset() { started_ = false; }
  bool started() const { return started_; }
  int64_t lastSampleTime() const { return previous_.utime; }

  // `sample` must be newer than the previous one (the caller checks timing). Calls
  // on_window(const ImuWindow&) for every window the interval up to `sample` completes, oldest first.
  template <class OnWindow>
  void add(const ImuSample& sample, OnWindow&& on_window) {
    if (!started_) {
      start(sample);
      return;
    }
    int64_t from = previous_.utime;
    while (true) {
      const int64_t to = std::min(sample.utime, window_end_);
      if (to > from) accumulate(sample, from, to);
      if (to == sample.utime) countClipping(sample);  // before its window can close
      if (to == window_end_) on_window(closeWindow(sample.seq));
      if (to == sample.utime) break;
      from = to;
    }
    previous_ = sample;
  }

 private:
  void start(const ImuSample& sample);
  void accumulate(const ImuSample& sample, int64_t from, int64_t to);
  void countClipping(const ImuSample& sample);
  const ImuWindow& closeWindow(int64_t seq);

  int64_t period_us_;
  double accel_clip_level_;
  bool started_ = false;
  ImuSample previous_;
  int64_t window_end_ = 0;
  Quat turn_ = identityQuat();  // body at the window start to body now
  ImuWindow window_;  // being accumulated
  ImuWindow closed_;  // the last completed one
};

}  // namespace sdlqr::estimator
