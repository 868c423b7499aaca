#include "sdlqr/estimator/estimator_params.hpp"

#include <cmath>

namespace sdlqr::estimator {

namespace {

bool positive(double value) { return std::isfinite(value) && value > 0.0; }

}  // namespace

int64_t EstimatorParams::outputPeriodUs() const { return static_cast<int64_t>(std::llround(1e6 / output_rate)); }

int EstimatorParams::historyCapacity() const {
  const double period = static_cast<double>(outputPeriodUs()) * 1e-6;
  // States at T, T - period, ..., back to T - history_length, plus the one just before it so a
  // capture time exactly history_length old still has a state at or before it.
  return static_cast<int>(std::ceil(history_length / period - 1e-9)) + 2;
}

EstimatorParams EstimatorParams::load(const ConfigReader& estimator) {
  estimator.allowOnly({"gyro_noise_density", "accel_noise_density", "gyro_bias_random_walk", "accel_bias_random_walk",
                       "gyro_range", "accel_range", "accel_clip_level", "clip_velocity_std", "initial_velocity_std", "initial_gyro_bias_std",
                       "initial_accel_bias_std", "vio_position_std", "vio_attitude_std", "output_rate",
                       "history_length", "vio_timeout", "reinit_after", "gate_chi2", "vio_reset_after", "quaternion_norm_tolerance",
                       "imu_max_gap", "imu_time_reset_count", "gravity"});
  EstimatorParams p;
  estimator.read("gyro_noise_density", p.gyro_noise_density);
  estimator.read("accel_noise_density", p.accel_noise_density);
  estimator.read("gyro_bias_random_walk", p.gyro_bias_random_walk);
  estimator.read("accel_bias_random_walk", p.accel_bias_random_walk);
  estimator.read("gyro_range", p.gyro_range);
  estimator.read("accel_range", p.accel_range);
  estimator.read("accel_clip_level", p.accel_clip_level);
  estimator.read("clip_velocity_std", p.clip_velocity_std);
  estimator.read("initial_velocity_std", p.initial_velocity_std);
  estimator.read("initial_gyro_bias_std", p.initial_gyro_bias_std);
  estimator.read("initial_accel_bias_std", p.initial_accel_bias_std);
  estimator.read("vio_position_std", p.vio_position_std);
  estimator.read("vio_attitude_std", p.vio_attitude_std);
  estimator.read("output_rate", p.output_rate);
  estimator.read("history_length", p.history_length);
  estimator.read("vio_timeout", p.vio_timeout);
  estimator.read("reinit_after", p.reinit_after);
  estimator.read("gate_chi2", p.gate_chi2);
  estimator.read("vio_reset_after", p.vio_reset_after);
  estimator.read("quaternion_norm_tolerance", p.quaternion_norm_tolerance);
  estimator.read("imu_max_gap", p.imu_max_gap);
  estimator.read("imu_time_reset_count", p.imu_time_reset_count);
  estimator.read("gravity", p.gravity);
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(estimator.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string EstimatorParams::invalidReason() const {
  if (!positive(gyro_noise_density)) return "gyro_noise_density: must be finite and > 0";
  if (!positive(accel_noise_density)) return "accel_noise_density: must be finite and > 0";
  if (!positive(gyro_bias_random_walk)) return "gyro_bias_random_walk: must be finite and > 0";
  if (!positive(accel_bias_random_walk)) return "accel_bias_random_walk: must be finite and > 0";
  if (!positive(gyro_range)) return "gyro_range: must be finite and > 0";
  if (!positive(accel_range)) return "accel_range: must be finite and > 0";
  // Above accel_range a reading is rejected, so a higher clip level could never be seen.
  if (!(positive(accel_clip_level) && accel_clip_level <= accel_range)) {
    return "accel_clip_level: must be > 0 and <= accel_range";
  }
  if (!positive(clip_velocity_std)) return "clip_velocity_std: must be finite and > 0";
  if (!positive(initial_velocity_std)) return "initial_velocity_std: must be finite and > 0";
  if (!positive(initial_gyro_bias_std)) return "initial_gyro_bias_std: must be finite and > 0";
  if (!positive(initial_accel_bias_std)) return "initial_accel_bias_std: must be finite and > 0";
  if (!positive(vio_position_std)) return "vio_position_std: must be finite and > 0";
  if (!positive(vio_attitude_std)) return "vio_attitude_std: must be finite and > 0";
  if (!(std::isfinite(output_rate) && output_rate >= 1.0 && output_rate <= 1000.0)) {
    return "output_rate: must be in [1, 1000] Hz";
  }
  const double period_us = 1e6 / output_rate;
  if (std::abs(period_us - std::round(period_us)) > 1e-6) {
    return "output_rate: 1e6 / output_rate must be a whole number of microseconds (e.g. 250, 200, 500)";
  }
  // 150 ms covers the 30-50 ms VIO latency of the simulator with margin for a late bus; 2 s bounds memory.
  if (!(std::isfinite(history_length) && history_length >= 0.15 && history_length <= 2.0)) {
    return "history_length: must be in [0.15, 2] s";
  }
  if (history_length * output_rate < 2.0) return "history_length: must span at least two output periods";
  if (!positive(vio_timeout)) return "vio_timeout: must be finite and > 0";
  if (!(std::isfinite(reinit_after) && reinit_after > vio_timeout)) return "reinit_after: must be finite and > vio_timeout";
  if (!positive(gate_chi2)) return "gate_chi2: must be finite and > 0";
  // Past reinit_after the next pose re-initialises anyway; a reset must come before that.
  if (!(positive(vio_reset_after) && vio_reset_after < reinit_after)) {
    return "vio_reset_after: must be > 0 and < reinit_after";
  }
  if (!(std::isfinite(quaternion_norm_tolerance) && quaternion_norm_tolerance > 0.0 && quaternion_norm_tolerance < 0.5)) {
    return "quaternion_norm_tolerance: must be in (0, 0.5)";
  }
  if (!(std::isfinite(imu_max_gap) && imu_max_gap > 0.0 && imu_max_gap <= 1.0)) return "imu_max_gap: must be in (0, 1] s";
  if (imu_time_reset_count < 1) return "imu_time_reset_count: must be >= 1";
  if (!positive(gravity)) return "gravity: must be finite and > 0";
  return {};
}

}  // namespace sdlqr::estimator
