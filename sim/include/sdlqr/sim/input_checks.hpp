#pragma once
// Acceptance of the simulator's inputs. A malformed MOTOR_CMD or DISTURBANCE is dropped and
// counted under the reason's counter name (DESIGN §7), never applied.

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/sim/sim_params.hpp"

namespace sdlqr::sim {

enum class MotorCommandFault { kNone, kNonFinite, kThrustRange, kMode };
enum class DisturbanceFault { kNone, kNonFinite, kDuration, kForce, kTorque, kHoldGains, kMode, kQueueFull };

inline constexpr MotorCommandFault kAllMotorCommandFaults[] = {MotorCommandFault::kNonFinite,
                                                               MotorCommandFault::kThrustRange, MotorCommandFault::kMode};
inline constexpr DisturbanceFault kAllDisturbanceFaults[] = {
    DisturbanceFault::kNonFinite, DisturbanceFault::kDuration,  DisturbanceFault::kForce,     DisturbanceFault::kTorque,
    DisturbanceFault::kHoldGains, DisturbanceFault::kMode,      DisturbanceFault::kQueueFull};

// Setpoints must be finite and within [0, 2 x max_rotor_thrust]: a little above the maximum is
// saturation, far above is a broken sender.
MotorCommandFault checkMotorCommand(const MotorCommand& command, const VehicleParams& vehicle);
// Finite, 0 <= duration <= max_duration, |force|, |torque| and the hold gains within the limits.
DisturbanceFault checkDisturbance(const Disturbance& disturbance, const DisturbanceLimits& limits);

// HEARTBEAT counter names, e.g. "reject.motor_cmd.nonfinite".
const char* counterName(MotorCommandFault fault);
const char* counterName(DisturbanceFault fault);

}  // namespace sdlqr::sim
