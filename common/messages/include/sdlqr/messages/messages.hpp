#pragma once
// Plain message structs: what the libraries exchange. They are generated from lcmtypes/*.lcm
// (sdlqr/lcmtypes/generated/plain.hpp, in the build folder), field for field with the units of
// the .lcm files; common/bus converts between them and the lcm-gen classes, so generated LCM
// types never reach algorithm code and the in-process closed loop needs no bus. Below: the
// members the .lcm files declare with @method, which are logic, not schema.

#include "sdlqr/lcmtypes/generated/plain.hpp"

namespace sdlqr {

inline State StateEstimate::state() const { return makeState(position, orientation, velocity); }

inline Input RateCommand::input() const { return makeInput(body_rate, thrust); }

}  // namespace sdlqr
