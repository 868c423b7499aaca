#pragma once
// The COMMAND the controller tests send (one translation unit per test binary: declared once).

#include "sdlqr/controller/reference_generator.hpp"

namespace sdlqr::controller::test {

inline Command command(CommandType type, const Vec3& position = Vec3::Zero(), double yaw = 0.0) {
  Command c;
  c.command = type;
  c.position = position;
  c.yaw = yaw;
  return c;
}

}  // namespace sdlqr::controller::test
