#include "sdlqr/lowlevel/ground_detector.hpp"

#include <cmath>

#include "sdlqr/lowlevel/low_pass.hpp"

namespace sdlqr::lowlevel {

GroundDetectorParams::GroundDetectorParams() { declaration().setDefaults(*this); }

const ParamTable<GroundDetectorParams>& GroundDetectorParams::declaration() {
  static const ParamTable<GroundDetectorParams> table = [] {
    using P = GroundDetectorParams;
    ParamTable<P> t("ground contact seen through the IMU alone");
    t.number("filter_cutoff_hz", &P::filter_cutoff_hz, 5.0, "Hz", Range::openClosed(0.0, 100.0), "low-pass on |f| and |omega|");
    t.number("accel_tolerance", &P::accel_tolerance, 0.5, "m/s^2", Range::open(0.0, 5.0), "at rest: | |f| - g | below this");
    t.number("gyro_tolerance", &P::gyro_tolerance, 0.2, "rad/s", Range::open(0.0, 5.0), "at rest: |omega| below this");
    t.number("impact_threshold", &P::impact_threshold, 5.0, "m/s^2", Range::above(0.0),
             "body-z specific force above the rotors' share");
    t.number("landed_thrust_ratio", &P::landed_thrust_ratio, 0.8, "-", Range::open(0.0, 1.0),
             "thrust command below ratio * hover counts as landing");
    t.number("landed_time", &P::landed_time, 1.0, "s", Range::above(0.0), "at rest with thrust below hover -> auto-disarm");
    return t;
  }();
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
