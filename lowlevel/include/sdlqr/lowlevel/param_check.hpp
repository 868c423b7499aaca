#pragma once
// Turns an invalidReason() text "key: reason" into a ConfigError naming the full key path,
// the way VehicleParams and LqrParams report bad values.

#include <string>

#include "sdlqr/config/config.hpp"

namespace sdlqr::lowlevel {

inline void throwIfInvalid(const ConfigReader& reader, const std::string& reason) {
  if (reason.empty()) return;
  const auto colon = reason.find(':');
  if (colon == std::string::npos) throw ConfigError(reader.path(), reason);
  throw ConfigError(reader.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
}

// Prefixes the key of a nested struct's reason: ("rate_control", "p[0]: must be > 0").
inline std::string nestedReason(const std::string& section, const std::string& reason) {
  return reason.empty() ? reason : section + "." + reason;
}

}  // namespace sdlqr::lowlevel
