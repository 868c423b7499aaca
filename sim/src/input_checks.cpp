#include "sdlqr/sim/input_checks.hpp"

#include <cmath>

namespace sdlqr::sim {

RejectReason checkMotorCommand(const MotorCommand& command, const VehicleParams& vehicle) {
  if (!command.thrust.allFinite()) return RejectReason::kNonFinite;
  for (int i = 0; i < 4; ++i) {
    if (command.thrust[i] < 0.0 || command.thrust[i] > 2.0 * vehicle.max_rotor_thrust) {
      return RejectReason::kOutOfRange;
    }
  }
  const auto mode = static_cast<int>(command.mode);
  if (mode < static_cast<int>(MotorMode::kDisarmed) || mode > static_cast<int>(MotorMode::kIdle)) {
    return RejectReason::kBadEnum;
  }
  return RejectReason::kNone;
}

RejectReason checkDisturbance(const Disturbance& d, const DisturbanceLimits& limits) {
  if (!std::isfinite(d.duration) || !d.force.allFinite() || !d.torque.allFinite() || !d.hold_position.allFinite() ||
      !std::isfinite(d.hold_stiffness) || !std::isfinite(d.hold_damping)) {
    return RejectReason::kNonFinite;
  }
  if (d.duration < 0.0 || d.duration > limits.max_duration) return RejectReason::kOutOfRange;
  if (d.force.norm() > limits.max_force) return RejectReason::kOutOfRange;
  if (d.torque.norm() > limits.max_torque) return RejectReason::kOutOfRange;
  const auto mode = static_cast<int>(d.mode);
  if (mode != static_cast<int>(DisturbanceMode::kForce) && mode != static_cast<int>(DisturbanceMode::kHold)) {
    return RejectReason::kBadEnum;
  }
  if (d.mode == DisturbanceMode::kHold &&
      (d.hold_stiffness < 0.0 || d.hold_stiffness > limits.max_stiffness || d.hold_damping < 0.0 ||
       d.hold_damping > limits.max_damping)) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

}  // namespace sdlqr::sim
