#include "sdlqr/lowlevel/ground_detector.hpp"

#include <cmath>

#include "sdlqr/lowlevel/low_pass.hpp"

#include "ground_detector_rows.hpp"

namespace sdlqr::lowlevel {

GroundDetectorParams::GroundDetectorParams() { declaration().setDefaults(*this); }

const ParamTable<GroundDetectorParams>& GroundDetectorParams::declaration() {
  static const ParamTable<GroundDetectorParams> table = groundDetectorParamsRows();
  return table;
}

GroundDetector::GroundDetector(const GroundDetectorParams& params, double gravity)
    : params_(params), gravity_(gravity) {}

void GroundDetector::reset() {
  initialized_ = false;
  specific_force_ = 0.0;
  rotation_rate_ = 0.0;
  at_rest_ = false;
  impact_ = false;
  body_z_force_ = 0.0;
}

void GroundDetector::update(const Vec3& gyro, const Vec3& accel, double rotor_specific_force, double dt) {
  if (!initialized_) {
    specific_force_ = accel.norm();
    rotation_rate_ = gyro.norm();
    body_z_force_ = accel.z();
    initialized_ = true;
  }
  const double alpha = lowPassAlpha(params_.filter_cutoff_hz, dt);
  specific_force_ += alpha * (accel.norm() - specific_force_);
  rotation_rate_ += alpha * (gyro.norm() - rotation_rate_);
  at_rest_ = std::abs(specific_force_ - gravity_) < params_.accel_tolerance && rotation_rate_ < params_.gyro_tolerance;
  impact_ = accel.z() - rotor_specific_force > params_.impact_threshold;
  body_z_force_ += alpha * (accel.z() - body_z_force_);
}

}  // namespace sdlqr::lowlevel
