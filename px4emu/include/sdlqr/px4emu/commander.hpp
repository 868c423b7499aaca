#pragma once
// PX4's Commander as far as offboard control goes, on the emulated PX4's clock (simulation time):
//   offboard signal   present while the last setpoint is younger than COM_OF_LOSS_T
//                     (HealthAndArmingChecks/checks/offboardCheck.cpp)
//   DO_SET_MODE       OFFBOARD only with the signal present, else TEMPORARILY_REJECTED (Commander.cpp);
//                     Hold, Land and Position accepted; other modes UNSUPPORTED here
//   ARM               on the ground with a valid estimate, and in OFFBOARD with the signal present,
//                     else TEMPORARILY_REJECTED; DISARM on the ground, in the air only forced (21196)
//   armed in OFFBOARD the signal lost -> COM_OBL_RC_ACT's mode (Land or Hold), counted
// Pure; the emulator core (emulator_core.hpp) flies what the mode says.

#include <cstdint>

#include "sdlqr/mavlink/messages.hpp"
#include "sdlqr/px4/px4_modes.hpp"
#include "sdlqr/px4emu/emulator_params.hpp"

namespace sdlqr::px4emu {

struct CommanderCounts {
  int64_t offboard_entered = 0;
  int64_t offboard_refused = 0;  // asked without the signal
  int64_t offboard_lost = 0;     // left for COM_OBL_RC_ACT
  int64_t arms = 0, arms_refused = 0, disarms = 0, disarms_refused = 0;
};

class Commander {
 public:
  explicit Commander(const EmulatorParams& params) : params_(params) {}

  // The MAV_RESULT of each command.
  uint8_t setMode(const mavlink::CommandLong& command, int64_t now_us);
  uint8_t armDisarm(const mavlink::CommandLong& command, int64_t now_us, bool on_ground, bool estimate_ok);
  void onSetpoint(int64_t now_us) { last_setpoint_us_ = now_us; }
  // The land detector disarmed the vehicle (PX4's COM_DISARM_LAND).
  void onAutoDisarm();
  // The offboard-loss rule; true when it left OFFBOARD now.
  bool update(int64_t now_us);

  bool armed() const { return armed_; }
  px4::FlightMode mode() const { return mode_; }
  bool offboardSignal(int64_t now_us) const;
  const CommanderCounts& counts() const { return counts_; }

 private:
  EmulatorParams params_;
  bool armed_ = false;
  px4::FlightMode mode_{px4::MainMode::kPosition, 0};  // PX4's default mode after boot
  int64_t last_setpoint_us_ = -1;
  CommanderCounts counts_;
};

}  // namespace sdlqr::px4emu
