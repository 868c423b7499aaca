#include "sdlqr/lowlevel/ground_detector.hpp"

#include <cmath>

#include "sdlqr/lowlevel/low_pass.hpp"
#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::lowlevel {

GroundDetectorParams GroundDetectorParams::load(const ConfigReader& reader) {
  reader.allowOnly({"filter_cutoff_hz", "accel_tolerance", "gyro_tolerance", "impact_threshold", "landed_thrust_ratio",
                    "landed_time"});
  GroundDetectorParams params;
  reader.read("filter_cutoff_hz", params.filter_cutoff_hz);
  reader.read("accel_tolerance", params.accel_tolerance);
  reader.read("gyro_tolerance", params.gyro_tolerance);
  reader.read("impact_threshold", params.impact_threshold);
  reader.read("landed_thrust_ratio", params.landed_thrust_ratio);
  reader.read("landed_time", params.landed_time);
  throwIfInvalid(reader, params.invalidReason());
  return params;
}

std::string GroundDetectorParams::invalidReason() const {
  if (!(filter_cutoff_hz > 0.0 && filter_cutoff_hz <= 100.0)) return "filter_cutoff_hz: must be in (0, 100] Hz";
  if (!(accel_tolerance > 0.0 && accel_tolerance < 5.0)) return "accel_tolerance: must be in (0, 5) m/s^2";
  if (!(gyro_tolerance > 0.0 && gyro_tolerance < 5.0)) return "gyro_tolerance: must be in (0, 5) rad/s";
  if (!(impact_threshold > 0.0 && std::isfinite(impact_threshold))) return "impact_threshold: must be > 0";
  if (!(landed_thrust_ratio > 0.0 && landed_thrust_ratio < 1.0)) return "landed_thrust_ratio: must be in (0, 1)";
  if (!(landed_time > 0.0 && std::isfinite(landed_time))) return "landed_time: must be > 0";
  return {};
}

GroundDetector::GroundDetector(const GroundDetectorParams& params, double gravity)
    : params_(params), gravity_(gravity) {}

void GroundDetector::reset() {
  initialized_ = false;
  specific_force_ = 0.0;
  rotation_rate_ = 0.0;
  at_rest_ = false;
  impact_ = false;
}

void GroundDetector::update(const Vec3& gyro, const Vec3& accel, double rotor_specific_force, double dt) {
  if (!initialized_) {
    specific_force_ = accel.norm();
    rotation_rate_ = gyro.norm();
    initialized_ = true;
  }
  const double alpha = lowPassAlpha(params_.filter_cutoff_hz, dt);
  specific_force_ += alpha * (accel.norm() - specific_force_);
  rotation_rate_ += alpha * (gyro.norm() - rotation_rate_);
  at_rest_ = std::abs(specific_force_ - gravity_) < params_.accel_tolerance && rotation_rate_ < params_.gyro_tolerance;
  impact_ = accel.z() - rotor_specific_force > params_.impact_threshold;
}

}  // namespace sdlqr::lowlevel
