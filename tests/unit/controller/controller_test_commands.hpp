#pragma once
// The COMMAND and STATE_EST the controller tests send (one translation unit per test binary:
// declared once).

#include "sdlqr/controller/reference_generator.hpp"

namespace sdlqr::controller::test {

inline Command command(CommandType type, const Vec3& position = Vec3::Zero(), double yaw = 0.0) {
  Command c;
  c.command = type;
  c.position = position;
  c.yaw = yaw;
  return c;
}

// A STATE_EST at t seconds of simulation time at p; the caller sets what else its case needs.
inline StateEstimate estimate(double t, const Vec3& p, EstimatorStatus status = EstimatorStatus::kOk) {
  StateEstimate e;
  e.utime = static_cast<int64_t>(t * 1e6);
  e.position = p;
  e.status = status;
  return e;
}

}  // namespace sdlqr::controller::test
