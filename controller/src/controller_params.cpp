#include "sdlqr/controller/controller_params.hpp"

namespace sdlqr::controller {

ControllerParams ControllerParams::load(const ConfigReader& controller) {
  controller.allowOnly({"rate_hz", "max_prediction_s", "gains_stale_s", "gains_fallback_s", "max_position_error", "max_velocity_error",
                        "takeoff_speed", "landing_speed", "landed_speed", "landed_time", "landing_undershoot",
                        "rejoin_height", "tracking"});
  ControllerParams p;
  controller.read("rate_hz", p.rate_hz);
  controller.read("max_prediction_s", p.max_prediction_s);
  controller.read("gains_stale_s", p.gains_stale_s);
  controller.read("gains_fallback_s", p.gains_fallback_s);
  controller.read("max_position_error", p.max_position_error);
  controller.read("max_velocity_error", p.max_velocity_error);
  controller.read("takeoff_speed", p.takeoff_speed);
  controller.read("landing_speed", p.landing_speed);
  controller.read("landed_speed", p.landed_speed);
  controller.read("landed_time", p.landed_time);
  controller.read("landing_undershoot", p.landing_undershoot);
  controller.read("rejoin_height", p.rejoin_height);
  std::string tracking = p.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial";
  controller.read("tracking", tracking);
  if (tracking == "spatial") {
    p.tracking = ReferenceMode::kSpatial;
  } else if (tracking == "temporal") {
    p.tracking = ReferenceMode::kTemporal;
  } else {
    throw ConfigError(controller.keyPath("tracking"), "expected spatial or temporal");
  }
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(controller.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string ControllerParams::invalidReason() const {
  if (!(rate_hz >= 1.0 && rate_hz <= 1000.0)) return "rate_hz: must be in [1, 1000] Hz";
  if (!(max_prediction_s >= 0.0 && max_prediction_s <= 0.02)) return "max_prediction_s: must be in [0, 0.02] s";
  if (!(gains_stale_s > 0.0)) return "gains_stale_s: must be > 0";
  if (!(gains_fallback_s > gains_stale_s)) return "gains_fallback_s: must be > gains_stale_s";
  if (!(max_position_error > 0.0)) return "max_position_error: must be > 0";
  if (!(max_velocity_error > 0.0)) return "max_velocity_error: must be > 0";
  if (!(takeoff_speed > 0.0 && takeoff_speed <= 5.0)) return "takeoff_speed: must be in (0, 5] m/s";
  if (!(landing_speed > 0.0 && landing_speed <= 2.0)) return "landing_speed: must be in (0, 2] m/s";
  if (!(landed_speed > 0.0)) return "landed_speed: must be > 0";
  if (!(landed_time >= 0.0)) return "landed_time: must be >= 0";
  if (!(landing_undershoot >= 0.0 && landing_undershoot <= 2.0)) return "landing_undershoot: must be in [0, 2] m";
  if (!(rejoin_height > 0.0 && rejoin_height <= 10.0)) return "rejoin_height: must be in (0, 10] m";
  return {};
}

}  // namespace sdlqr::controller
