#pragma once
// Ground contact as a constraint on the plane z = 0. A vehicle on the ground rests exactly at
// z = 0, level, motionless (legs and friction), so a landed vehicle never jitters or sinks. Each
// step is integrated as free flight; if the result lies below the ground the vehicle is (back)
// on it. Lift-off therefore happens exactly when the net upward force exceeds the weight.

#include "sdlqr/sim/rigid_body.hpp"
#include "sdlqr/sim/sim_params.hpp"

namespace sdlqr::sim {

// The same vehicle standing on its legs at the point where it touched: z = 0, level with its
// yaw kept, no velocity, no rotation.
BodyState restingOnGround(const BodyState& touching);

// A touchdown faster than crash_speed (vertical) or tilted beyond crash_tilt (a flip) breaks the
// vehicle. `touching` is the first state found at or below the ground.
bool isCrash(const BodyState& touching, const GroundParams& ground);

}  // namespace sdlqr::sim
