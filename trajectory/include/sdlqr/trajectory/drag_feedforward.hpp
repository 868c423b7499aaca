#pragma once
// The feed-forward against the model's rotor drag (lqr.model_rotor_drag, issue 25): a reference is
// made drag-free (trajectory samples, transitions, holds), so the thrust and attitude it names
// accelerate a vehicle without drag. With drag, the plant needs c z_b = a + g e_z + s(c) R D R^T v
// (model.hpp RotorDrag) to fly the same path; the controller remaps the reference of each tick to
// that, and the feasibility check (feasibility.hpp) judges the inputs of that remap: one computation
// of what is flown for both.

#include "sdlqr/math/model.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::trajectory {

// The reference (x, u) re-derived through the flat map with drag (trajectory/flatness.hpp) from its
// own flat outputs: position, velocity, acceleration c z_b - g e_z, jerk from the body rates (its
// thrust rate is not in a reference: taken as zero), heading and heading rate. Position and
// velocity are kept; attitude (in x's quaternion hemisphere), body rates and thrust change. No
// drag, or a singular reference (c ~ 0): unchanged.
void compensateRotorDrag(State& x, Input& u, double gravity, const RotorDrag& drag);

// The inputs the controller flies for the reference (x, u): u after compensateRotorDrag.
Input flownInput(const State& x, const Input& u, double gravity, const RotorDrag& drag);

}  // namespace sdlqr::trajectory
