#include "sdlqr/health/watchdog.hpp"

#include <cmath>

namespace sdlqr {

bool Watchdog::check(double now_s) {
  const bool silent = started() && now_s - last_feed_s_ > timeout_s_;
  if (silent && !expired_) ++timeouts_;
  expired_ = silent;
  return expired_;
}

FaultParams FaultParams::load(const ConfigReader& faults) {
  faults.allowOnly({"controller_state_timeout", "lowlevel_imu_timeout", "state_max_jump", "state_jump_confirmations"});
  FaultParams p;
  faults.read("controller_state_timeout", p.controller_state_timeout_s);
  faults.read("lowlevel_imu_timeout", p.lowlevel_imu_timeout_s);
  faults.read("state_max_jump", p.state_max_jump_s);
  faults.read("state_jump_confirmations", p.state_jump_confirmations);
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(faults.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string FaultParams::invalidReason() const {
  auto positive = [](double v, double max) { return std::isfinite(v) && v > 0.0 && v <= max; };
  if (!positive(controller_state_timeout_s, 10.0)) return "controller_state_timeout: must be in (0, 10] s";
  if (!positive(lowlevel_imu_timeout_s, 10.0)) return "lowlevel_imu_timeout: must be in (0, 10] s";
  if (!positive(state_max_jump_s, 60.0)) return "state_max_jump: must be in (0, 60] s";
  if (state_jump_confirmations < 1 || state_jump_confirmations > 1000) {
    return "state_jump_confirmations: must be in [1, 1000]";
  }
  return {};
}

}  // namespace sdlqr
