#pragma once
// Conversion between the lcm-gen classes and the plain structs of sdlqr/messages/messages.hpp:
// bus::fromLcm(const imu_t&) -> ImuSample, bus::toLcm(const ImuSample&) -> imu_t, and so for
// every type of lcmtypes/. Generated field for field from the .lcm files
// (sdlqr/lcmtypes/generated/convert.hpp); converting copies only, validation lives in the
// libraries.

#include "sdlqr/lcmtypes/generated/convert.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::bus {

using ::sdlqr::fromLcm;
using ::sdlqr::toLcm;

}  // namespace sdlqr::bus
