#pragma once
// The lowlevel's name for the common "key: reason" -> ConfigError conversion (config.hpp), used
// for the checks against other sections (LowlevelParams::invalidReasonFor).

#include "sdlqr/config/config.hpp"

namespace sdlqr::lowlevel {

using ::sdlqr::throwIfInvalid;

}  // namespace sdlqr::lowlevel
