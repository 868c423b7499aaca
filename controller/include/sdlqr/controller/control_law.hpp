#pragma once
// The paper's feedback policy, eq. (15): u = u0 + K (x - x0), with the input limits of §III-B.

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::controller {

struct ControlOutput {
  Input u = Input::Zero();
  bool rate_saturated = false;    // ||omega|| clipped to omega_max
  bool thrust_saturated = false;  // c clipped to [c_min, c_max]
  double thrust_demand = 0.0;     // [m/s^2] c before the clip: how far beyond the limits the law asked
  bool headroom_scaled = false;   // applyControlLawWithinThrust scaled the feedback down
};

struct ErrorBounds {
  double max_position_error = 1.0;  // [m]
  double max_velocity_error = 2.0;  // [m/s]
};

// x - x_ref with position and velocity errors bounded in norm. q and -q are the same attitude,
// but K acts on the quaternion linearly and was built at q_lin: K at -q_lin is K at q_lin with its
// quaternion columns negated. So q is first taken in the hemisphere of q_lin, then q_ref in the
// hemisphere of that q (docs/architecture.md §3); the command is then the same for every sign choice.
State stateError(const State& x, const State& x_ref, const Quat& q_lin, const ErrorBounds& bounds);

// u with its body rates scaled to ||omega|| <= omega_max and its thrust clipped to [c_min, c_max]
// (a projection onto a convex set: it never enlarges the difference of two commands).
ControlOutput applyInputLimits(const Input& u, const LqrParams& limits);

// u_ref + K (x - x_ref), body rates scaled to ||omega|| <= omega_max, thrust clipped to [c_min, c_max].
// q_lin: the quaternion K was linearized at (GainSet::x_lin).
ControlOutput applyControlLaw(const GainMatrix& K, const Quat& q_lin, const State& x, const State& x_ref,
                              const Input& u_ref, const LqrParams& limits, const ErrorBounds& bounds);

// As applyControlLaw, but where u_ref + K (x - x_ref) would ask for thrust outside [c_min, c_max]
// the feedback K (x - x_ref) is scaled down (rates with it) until the thrust is at the limit: the
// paper's bounded errors (§IV-A) made as tight as the thrust leaves room for. sdlqr_integral flies
// with it: its 12-state K is ~10 % stiffer than the paper's and leaned on c_max under a held pull.
ControlOutput applyControlLawWithinThrust(const GainMatrix& K, const Quat& q_lin, const State& x, const State& x_ref,
                                          const Input& u_ref, const LqrParams& limits, const ErrorBounds& bounds);

}  // namespace sdlqr::controller
