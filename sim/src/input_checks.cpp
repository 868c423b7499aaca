#include "sdlqr/sim/input_checks.hpp"

#include <cmath>

namespace sdlqr::sim {

MotorCommandFault checkMotorCommand(const MotorCommand& command, const VehicleParams& vehicle) {
  if (!command.thrust.allFinite()) return MotorCommandFault::kNonFinite;
  for (int i = 0; i < 4; ++i) {
    if (command.thrust[i] < 0.0 || command.thrust[i] > 2.0 * vehicle.max_rotor_thrust) {
      return MotorCommandFault::kThrustRange;
    }
  }
  const auto mode = static_cast<int>(command.mode);
  if (mode < static_cast<int>(MotorMode::kDisarmed) || mode > static_cast<int>(MotorMode::kIdle)) {
    return MotorCommandFault::kMode;
  }
  return MotorCommandFault::kNone;
}

DisturbanceFault checkDisturbance(const Disturbance& d, const DisturbanceLimits& limits) {
  if (!std::isfinite(d.duration) || !d.force.allFinite() || !d.torque.allFinite() || !d.hold_position.allFinite() ||
      !std::isfinite(d.hold_stiffness) || !std::isfinite(d.hold_damping)) {
    return DisturbanceFault::kNonFinite;
  }
  if (d.duration < 0.0 || d.duration > limits.max_duration) return DisturbanceFault::kDuration;
  if (d.force.norm() > limits.max_force) return DisturbanceFault::kForce;
  if (d.torque.norm() > limits.max_torque) return DisturbanceFault::kTorque;
  const auto mode = static_cast<int>(d.mode);
  if (mode != static_cast<int>(DisturbanceMode::kForce) && mode != static_cast<int>(DisturbanceMode::kHold)) {
    return DisturbanceFault::kMode;
  }
  if (d.mode == DisturbanceMode::kHold &&
      (d.hold_stiffness < 0.0 || d.hold_stiffness > limits.max_stiffness || d.hold_damping < 0.0 ||
       d.hold_damping > limits.max_damping)) {
    return DisturbanceFault::kHoldGains;
  }
  return DisturbanceFault::kNone;
}

const char* counterName(MotorCommandFault fault) {
  switch (fault) {
    case MotorCommandFault::kNone: return "accept.motor_cmd";
    case MotorCommandFault::kNonFinite: return "reject.motor_cmd.nonfinite";
    case MotorCommandFault::kThrustRange: return "reject.motor_cmd.thrust_range";
    case MotorCommandFault::kMode: return "reject.motor_cmd.mode";
  }
  return "reject.motor_cmd.unknown";
}

const char* counterName(DisturbanceFault fault) {
  switch (fault) {
    case DisturbanceFault::kNone: return "accept.disturbance";
    case DisturbanceFault::kNonFinite: return "reject.disturbance.nonfinite";
    case DisturbanceFault::kDuration: return "reject.disturbance.duration";
    case DisturbanceFault::kForce: return "reject.disturbance.force";
    case DisturbanceFault::kTorque: return "reject.disturbance.torque";
    case DisturbanceFault::kHoldGains: return "reject.disturbance.hold_gains";
    case DisturbanceFault::kMode: return "reject.disturbance.mode";
    case DisturbanceFault::kQueueFull: return "reject.disturbance.queue_full";
  }
  return "reject.disturbance.unknown";
}

}  // namespace sdlqr::sim
