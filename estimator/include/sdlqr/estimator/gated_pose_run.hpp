#pragma once
// Tells a filter that has gone wrong from a VIO outlier. The chi-square gate keeps an outlier pose
// out of the filter; but when the filter itself is wrong (a velocity change the IMU could not
// measure, a VIO world frame that jumped on relocalisation) every following pose fails the gate
// too, and the filter would dead-reckon until the long re-initialisation timeout. Those poses
// agree with one another: from one to the next the innovation changes only by the VIO noise and
// by the filter's velocity error times the frame interval. Outliers do not.
//
// A run is a sequence of consecutive gated poses each within the gate of the previous one
// (innovation difference weighed by the sum of both innovation covariances). Once a run spans
// `reset_after` the caller resets the filter to the VIO; the slope of the position innovation
// over the run is the filter's velocity error, to be corrected at the same time. PX4 EKF2 resets
// after a time of failing innovations too; the agreement test is ours.
//
// Fixed size: running sums, no storage per pose.

#include <cstdint>

#include "sdlqr/estimator/error_state_ekf.hpp"

namespace sdlqr::estimator {

class GatedPoseRun {
 public:
  GatedPoseRun(double gate_chi2, int64_t reset_after_us) : gate_chi2_(gate_chi2), reset_after_us_(reset_after_us) {}

  void clear() { size_ = 0; }
  int size() const { return size_; }
  int64_t firstUtime() const { return first_utime_; }
  int64_t lastUtime() const { return last_utime_; }

  // Adds a gated pose (capture time after the previous one's). A pose that disagrees with the
  // previous one starts a new run. True when the run now spans at least reset_after.
  bool add(int64_t capture_utime, const PoseUpdateResult& gated);

  // [m/s] least-squares slope of the position innovation (pose minus filter, world) over the
  // run: the filter's velocity error. Zero for fewer than two poses.
  Vec3 positionDriftRate() const;
  // [m^2/s^2] per axis: that slope's variance for poses with position variance position_var.
  double positionDriftRateVariance(double position_var) const;

 private:
  void start(int64_t capture_utime);
  double spread() const;  // sum over the run of (t - mean t)^2 [s^2]

  double gate_chi2_;
  int64_t reset_after_us_;
  int size_ = 0;
  int64_t first_utime_ = 0;
  int64_t last_utime_ = 0;
  PoseVector last_innovation_ = PoseVector::Zero();
  PoseMatrix last_innovation_cov_ = PoseMatrix::Zero();
  // Sums for the regression, time in seconds since the run's first pose.
  double sum_t_ = 0.0;
  double sum_tt_ = 0.0;
  Vec3 sum_r_ = Vec3::Zero();
  Vec3 sum_tr_ = Vec3::Zero();
};

}  // namespace sdlqr::estimator
