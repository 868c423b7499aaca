#include "sdlqr/px4emu/commander.hpp"

#include <cmath>

namespace sdlqr::px4emu {

namespace result = mavlink::mav_result;
using px4::FlightMode;
using px4::MainMode;

bool Commander::offboardSignal(int64_t now_us) const {
  return last_setpoint_us_ >= 0 && static_cast<double>(now_us - last_setpoint_us_) * 1e-6 < params_.com_of_loss_t;
}

uint8_t Commander::setMode(const mavlink::CommandLong& command, int64_t now_us) {
  if ((static_cast<uint32_t>(command.param1) & mavlink::mav_mode_flag::kCustomModeEnabled) == 0) {
    return result::kUnsupported;  // base modes without a custom mode: not emulated
  }
  const FlightMode wanted{static_cast<MainMode>(static_cast<uint8_t>(command.param2)),
                          static_cast<uint8_t>(command.param3)};
  if (wanted.offboard()) {
    if (!offboardSignal(now_us)) {
      ++counts_.offboard_refused;
      return result::kTemporarilyRejected;
    }
    if (!mode_.offboard()) ++counts_.offboard_entered;
    mode_ = px4::kOffboardMode;
    return result::kAccepted;
  }
  if (wanted == px4::kHoldMode || wanted == px4::kLandMode || wanted.main == MainMode::kPosition) {
    mode_ = wanted;
    return result::kAccepted;
  }
  return result::kUnsupported;
}

uint8_t Commander::armDisarm(const mavlink::CommandLong& command, int64_t now_us, bool on_ground, bool estimate_ok) {
  const bool forced = std::abs(command.param2 - px4::kForceArmDisarm) < 0.5f;
  if (command.param1 == 0.0f) {
    if (!on_ground && !forced) {
      ++counts_.disarms_refused;
      return result::kDenied;
    }
    if (armed_) ++counts_.disarms;
    armed_ = false;
    return result::kAccepted;
  }
  if (command.param1 != 1.0f) return result::kDenied;  // MAV_BOOL: 0 or 1
  if (armed_) return result::kAccepted;
  // A forced arm over MAVLink still runs the checks (PX4's Commander: from_external).
  const bool mode_ready = !mode_.offboard() || offboardSignal(now_us);
  if (!on_ground || !estimate_ok || !mode_ready) {
    ++counts_.arms_refused;
    return result::kTemporarilyRejected;
  }
  armed_ = true;
  ++counts_.arms;
  return result::kAccepted;
}

void Commander::onAutoDisarm() {
  if (!armed_) return;
  armed_ = false;
  ++counts_.disarms;
}

bool Commander::update(int64_t now_us) {
  if (!armed_ || !mode_.offboard() || offboardSignal(now_us)) return false;
  mode_ = params_.com_obl_rc_act == kHoldAction ? px4::kHoldMode : px4::kLandMode;
  ++counts_.offboard_lost;
  return true;
}

}  // namespace sdlqr::px4emu
