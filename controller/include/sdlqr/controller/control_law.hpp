#pragma once
// The paper's feedback policy, eq. (15): u = u0 + K (x - x0), with the input limits of §III-B.

#include "sdlqr/common/params.hpp"
#include "sdlqr/common/types.hpp"

namespace sdlqr::controller {

struct ControlOutput {
  Input u = Input::Zero();
  bool rate_saturated = false;    // ||omega|| clipped to omega_max
  bool thrust_saturated = false;  // c clipped to [c_min, c_max]
};

struct ErrorBounds {
  double max_position_error = 1.0;  // [m]
  double max_velocity_error = 2.0;  // [m/s]
};

// x - x_ref with the reference quaternion moved into the hemisphere of q (q and -q are the same
// attitude; K is only valid for the nearby one) and position and velocity errors bounded in norm.
State stateError(const State& x, const State& x_ref, const ErrorBounds& bounds);

// u_ref + K (x - x_ref), body rates scaled to ||omega|| <= omega_max, thrust clipped to [c_min, c_max].
ControlOutput applyControlLaw(const GainMatrix& K, const State& x, const State& x_ref, const Input& u_ref,
                              const LqrParams& limits, const ErrorBounds& bounds);

}  // namespace sdlqr::controller
