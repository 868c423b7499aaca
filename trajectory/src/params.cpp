#include "sdlqr/trajectory/params.hpp"

#include <cmath>

namespace sdlqr::trajectory {

namespace {
bool positiveFinite(double value) { return std::isfinite(value) && value > 0.0; }
}  // namespace

TrajectoryParams TrajectoryParams::load(const ConfigReader& trajectory) {
  trajectory.allowOnly({"sample_dt", "check_dt", "height_offset", "laps", "periodic", "yaw", "fast_v_max",
                        "slow_v_max", "ellipse_speed", "ellipse_samples", "max_position_jump", "accel_mismatch_max"});
  TrajectoryParams p;
  trajectory.read("sample_dt", p.sample_dt);
  trajectory.read("check_dt", p.check_dt);
  trajectory.read("height_offset", p.height_offset);
  trajectory.read("laps", p.laps);
  trajectory.read("periodic", p.periodic);
  trajectory.read("yaw", p.yaw);
  trajectory.read("fast_v_max", p.fast_v_max);
  trajectory.read("slow_v_max", p.slow_v_max);
  trajectory.read("ellipse_speed", p.ellipse_speed);
  trajectory.read("ellipse_samples", p.ellipse_samples);
  trajectory.read("max_position_jump", p.max_position_jump);
  trajectory.read("accel_mismatch_max", p.accel_mismatch_max);
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(trajectory.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string TrajectoryParams::invalidReason() const {
  if (!positiveFinite(sample_dt) || sample_dt > 10.0) return "sample_dt: must be in (0, 10] s";
  if (!positiveFinite(check_dt) || check_dt > sample_dt) return "check_dt: must be > 0 and <= sample_dt";
  if (!std::isfinite(height_offset)) return "height_offset: must be finite";
  if (laps < 1 || laps > 100) return "laps: must be in [1, 100]";
  if (!std::isfinite(yaw)) return "yaw: must be finite";
  if (!positiveFinite(fast_v_max)) return "fast_v_max: must be > 0";
  if (!positiveFinite(slow_v_max)) return "slow_v_max: must be > 0";
  if (!positiveFinite(ellipse_speed)) return "ellipse_speed: must be > 0";
  if (ellipse_samples < 3 || ellipse_samples > 100000) return "ellipse_samples: must be in [3, 100000]";
  if (!positiveFinite(max_position_jump)) return "max_position_jump: must be > 0";
  if (!positiveFinite(accel_mismatch_max)) return "accel_mismatch_max: must be > 0";
  return {};
}

SampleChecks TrajectoryParams::sampleChecks() const {
  SampleChecks checks;
  checks.max_position_jump = max_position_jump;
  return checks;
}

}  // namespace sdlqr::trajectory
