#include "sdlqr/gains/gains_params.hpp"

namespace sdlqr::gains {

GainsParams GainsParams::load(const ConfigReader& gains) {
  gains.allowOnly({"rate_hz", "state_timeout_s"});
  GainsParams p;
  gains.read("rate_hz", p.rate_hz);
  gains.read("state_timeout_s", p.state_timeout_s);
  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(gains.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string GainsParams::invalidReason() const {
  if (!(rate_hz >= 0.1 && rate_hz <= 1000.0)) return "rate_hz: must be in [0.1, 1000] Hz";
  if (!(state_timeout_s > 0.0)) return "state_timeout_s: must be > 0";
  return {};
}

}  // namespace sdlqr::gains
