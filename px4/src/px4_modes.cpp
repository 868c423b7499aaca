#include "sdlqr/px4/px4_modes.hpp"

namespace sdlqr::px4 {

const char* modeName(FlightMode mode) {
  switch (mode.main) {
    case MainMode::kManual: return "manual";
    case MainMode::kAltitude: return "altitude";
    case MainMode::kPosition: return "position";
    case MainMode::kAcro: return "acro";
    case MainMode::kOffboard: return "offboard";
    case MainMode::kStabilized: return "stabilized";
    case MainMode::kAuto:
      switch (static_cast<AutoMode>(mode.sub)) {
        case AutoMode::kReady: return "auto.ready";
        case AutoMode::kTakeoff: return "takeoff";
        case AutoMode::kLoiter: return "hold";
        case AutoMode::kMission: return "mission";
        case AutoMode::kReturn: return "return";
        case AutoMode::kLand: return "land";
      }
      return "auto";
  }
  return "unknown";
}

}  // namespace sdlqr::px4
