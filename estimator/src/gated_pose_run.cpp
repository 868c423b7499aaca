#include "sdlqr/estimator/gated_pose_run.hpp"

#include <Eigen/Cholesky>

namespace sdlqr::estimator {

void GatedPoseRun::start(int64_t capture_utime) {
  size_ = 0;
  first_utime_ = capture_utime;
  sum_t_ = 0.0;
  sum_tt_ = 0.0;
  sum_r_.setZero();
  sum_tr_.setZero();
}

bool GatedPoseRun::add(int64_t capture_utime, const PoseUpdateResult& gated) {
  bool agrees = false;
  if (size_ > 0) {
    // Independent noise on both sides is the generous reading (both innovations share the
    // filter's error): a run is broken only by what no filter error could explain.
    const PoseVector change = gated.innovation - last_innovation_;
    const Eigen::LLT<PoseMatrix> llt(gated.innovation_cov + last_innovation_cov_);
    agrees = llt.info() == Eigen::Success && change.dot(llt.solve(change)) <= gate_chi2_;
  }
  if (!agrees) start(capture_utime);

  const double t = 1e-6 * static_cast<double>(capture_utime - first_utime_);
  const Vec3 r = gated.innovation.head<3>();
  ++size_;
  sum_t_ += t;
  sum_tt_ += t * t;
  sum_r_ += r;
  sum_tr_ += t * r;
  last_utime_ = capture_utime;
  last_innovation_ = gated.innovation;
  last_innovation_cov_ = gated.innovation_cov;
  return capture_utime - first_utime_ >= reset_after_us_;
}

double GatedPoseRun::spread() const {
  if (size_ < 2) return 0.0;
  return sum_tt_ - sum_t_ * sum_t_ / static_cast<double>(size_);
}

Vec3 GatedPoseRun::positionDriftRate() const {
  const double s = spread();
  if (!(s > 0.0)) return Vec3::Zero();
  return (sum_tr_ - sum_t_ * sum_r_ / static_cast<double>(size_)) / s;
}

double GatedPoseRun::positionDriftRateVariance(double position_var) const {
  const double s = spread();
  return s > 0.0 ? position_var / s : 0.0;
}

}  // namespace sdlqr::estimator
