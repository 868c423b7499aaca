#include "sdlqr/controller/control_law.hpp"

#include <algorithm>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::controller {

namespace {

Vec3 boundNorm(const Vec3& v, double max_norm) {
  const double norm = v.norm();
  return norm > max_norm ? Vec3(v * (max_norm / norm)) : v;
}

}  // namespace

State stateError(const State& x, const State& x_ref, const Quat& q_lin, const ErrorBounds& bounds) {
  State error;
  position(error) = boundNorm(position(x) - position(x_ref), bounds.max_position_error);
  const Quat q = quat::sameHemisphere(orientation(x), q_lin);
  orientation(error) = q - quat::sameHemisphere(orientation(x_ref), q);
  velocity(error) = boundNorm(velocity(x) - velocity(x_ref), bounds.max_velocity_error);
  return error;
}

ControlOutput applyControlLaw(const GainMatrix& K, const Quat& q_lin, const State& x, const State& x_ref,
                              const Input& u_ref, const LqrParams& limits, const ErrorBounds& bounds) {
  return applyInputLimits(u_ref + K * stateError(x, x_ref, q_lin, bounds), limits);
}

ControlOutput applyControlLawWithinThrust(const GainMatrix& K, const Quat& q_lin, const State& x, const State& x_ref,
                                          const Input& u_ref, const LqrParams& limits, const ErrorBounds& bounds) {
  const Input feedback = K * stateError(x, x_ref, q_lin, bounds);
  const double demand = u_ref[kThrust] + feedback[kThrust];
  double scale = 1.0;
  if (demand > limits.c_max && feedback[kThrust] > 0.0) {
    scale = std::max(0.0, (limits.c_max - u_ref[kThrust]) / feedback[kThrust]);
  } else if (demand < limits.c_min && feedback[kThrust] < 0.0) {
    scale = std::max(0.0, (limits.c_min - u_ref[kThrust]) / feedback[kThrust]);
  }
  ControlOutput out = applyInputLimits(u_ref + scale * feedback, limits);
  out.headroom_scaled = scale < 1.0;
  return out;
}

ControlOutput applyInputLimits(const Input& u, const LqrParams& limits) {
  ControlOutput out;
  out.u = u;
  const double rate_norm = bodyRate(out.u).norm();
  if (rate_norm > limits.omega_max) {
    bodyRate(out.u) *= limits.omega_max / rate_norm;
    out.rate_saturated = true;
  }
  out.thrust_demand = out.u[kThrust];
  const double thrust = std::clamp(out.u[kThrust], limits.c_min, limits.c_max);
  out.thrust_saturated = thrust != out.u[kThrust];
  out.u[kThrust] = thrust;
  return out;
}

}  // namespace sdlqr::controller
