#pragma once
// Acceptance of the simulator's inputs. A malformed MOTOR_CMD or DISTURBANCE is dropped and
// counted under its reason (common/health reject_reason.hpp), never applied.

#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/sim/sim_params.hpp"

namespace sdlqr::sim {

// Setpoints must be finite (kNonFinite), within [0, 2 x max_rotor_thrust] (kOutOfRange: a little
// above the maximum is saturation, far above is a broken sender) and of a known mode (kBadEnum).
RejectReason checkMotorCommand(const MotorCommand& command, const VehicleParams& vehicle);
// Finite, 0 <= duration <= max_duration, |force|, |torque| and the hold gains within the limits
// (kOutOfRange), a known mode (kBadEnum).
RejectReason checkDisturbance(const Disturbance& disturbance, const DisturbanceLimits& limits);

}  // namespace sdlqr::sim
