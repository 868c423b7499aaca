#pragma once
// How PX4 reports and takes its flight mode over MAVLink (PX4 px4_custom_mode.h, streams/
// HEARTBEAT.hpp, Commander.cpp): HEARTBEAT.custom_mode holds the main mode in bits 16-23 and the
// sub mode in bits 24-31; base_mode always has CUSTOM_MODE_ENABLED and SAFETY_ARMED when armed.
// MAV_CMD_DO_SET_MODE takes param1 = CUSTOM_MODE_ENABLED, param2 = main mode, param3 = sub mode.
// Shared by the bridge (reading PX4) and the emulated PX4 (reporting as PX4 does).

#include <cstdint>

namespace sdlqr::px4 {

enum class MainMode : uint8_t {
  kManual = 1,
  kAltitude = 2,
  kPosition = 3,
  kAuto = 4,
  kAcro = 5,
  kOffboard = 6,
  kStabilized = 7,
};

enum class AutoMode : uint8_t {  // sub modes of kAuto
  kReady = 1,
  kTakeoff = 2,
  kLoiter = 3,  // "Hold"
  kMission = 4,
  kReturn = 5,
  kLand = 6,
};

struct FlightMode {
  MainMode main = MainMode::kManual;
  uint8_t sub = 0;
  bool operator==(const FlightMode& o) const { return main == o.main && sub == o.sub; }
  bool operator!=(const FlightMode& o) const { return !(*this == o); }
  bool offboard() const { return main == MainMode::kOffboard; }
};

inline constexpr FlightMode kOffboardMode{MainMode::kOffboard, 0};
inline constexpr FlightMode kHoldMode{MainMode::kAuto, static_cast<uint8_t>(AutoMode::kLoiter)};
inline constexpr FlightMode kLandMode{MainMode::kAuto, static_cast<uint8_t>(AutoMode::kLand)};

constexpr uint32_t customModeOf(FlightMode mode) {
  return (static_cast<uint32_t>(mode.main) << 16) | (static_cast<uint32_t>(mode.sub) << 24);
}
constexpr FlightMode flightModeOf(uint32_t custom_mode) {
  return FlightMode{static_cast<MainMode>((custom_mode >> 16) & 0xFF), static_cast<uint8_t>((custom_mode >> 24) & 0xFF)};
}

const char* modeName(FlightMode mode);  // "offboard", "hold", "land", "manual", ...

inline constexpr uint8_t kAutopilotComponent = 1;      // MAV_COMP_ID_AUTOPILOT1
inline constexpr uint8_t kOnboardComputerComponent = 191;  // MAV_COMP_ID_ONBOARD_COMPUTER
inline constexpr float kForceArmDisarm = 21196.0f;     // MAV_CMD_COMPONENT_ARM_DISARM param2

}  // namespace sdlqr::px4
