#include "sdlqr/mission/throw_detector.hpp"

#include "sdlqr/math/quaternion.hpp"

#include "throw_detector_rows.hpp"

namespace sdlqr::mission {

ThrowModeParams::ThrowModeParams() { declaration().setDefaults(*this); }

const ParamTable<ThrowModeParams>& ThrowModeParams::declaration() {
  static const ParamTable<ThrowModeParams> table = throwModeParamsRows();
  return table;
}

ThrowDetector::ThrowDetector(const ThrowModeParams& params, double gravity) : params_(params), gravity_(gravity) {}

bool ThrowDetector::accelerationOf(const StateEstimate& estimate, Vec3& acceleration) const {
  const int64_t window_us = static_cast<int64_t>(params_.acceleration_window * 1e6);
  // The oldest sample still within the window (the ring holds the newest kRing).
  for (int back = count_; back >= 1; --back) {
    const Sample& s = ring_[static_cast<size_t>((next_ - back + kRing) % kRing)];
    const int64_t span = estimate.utime - s.utime;
    if (span <= window_us && span > 0) {
      acceleration = (estimate.velocity - s.velocity) / (1e-6 * static_cast<double>(span));
      return true;
    }
  }
  return false;
}

std::optional<ThrowDetection> ThrowDetector::onEstimate(const StateEstimate& estimate) {
  if (detected_ || estimate.status != EstimatorStatus::kOk) return std::nullopt;
  if (count_ > 0 && estimate.utime <= ring_[static_cast<size_t>((next_ - 1 + kRing) % kRing)].utime) {
    return std::nullopt;
  }
  Vec3 acceleration;
  const bool measured = accelerationOf(estimate, acceleration);
  ring_[static_cast<size_t>(next_)] = {estimate.utime, estimate.velocity};
  next_ = (next_ + 1) % kRing;
  if (count_ < kRing) ++count_;
  if (!measured) return std::nullopt;

  const Vec3 specific_force = acceleration + Vec3(0.0, 0.0, gravity_);
  const double vz = estimate.velocity.z();
  const bool free_falling = specific_force.z() < params_.free_fall_fraction * gravity_;
  const bool high_speed = estimate.velocity.norm() > params_.high_speed;
  const bool changing_height =
      params_.type == ThrowType::kThrow ? vz > params_.vertical_speed : vz < -params_.vertical_speed;
  const bool released = specific_force.norm() < gravity_;
  possible_ = (free_falling || high_speed) && changing_height && released;

  const int64_t window_us = static_cast<int64_t>(params_.confirm_window * 1e6);
  if (possible_ && (possible_since_utime_ < 0 || estimate.utime - possible_since_utime_ > window_us)) {
    possible_since_utime_ = estimate.utime;
    possible_velocity_z_ = vz;
  }
  const bool confirmed = possible_since_utime_ >= 0 && estimate.utime - possible_since_utime_ < window_us &&
                         vz - possible_velocity_z_ < -params_.confirm_velocity_drop;
  if (!confirmed) return std::nullopt;
  detected_ = true;
  ThrowDetection d;
  d.utime = estimate.utime;
  d.position = estimate.position;
  d.velocity = estimate.velocity;
  d.yaw = quat::yaw(estimate.orientation);
  return d;
}

}  // namespace sdlqr::mission
