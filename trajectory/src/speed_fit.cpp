#include "sdlqr/trajectory/speed_fit.hpp"

#include <cstdio>

namespace sdlqr::trajectory {

SpeedFit fitSpeed(const std::function<Trajectory(double)>& generate, double requested_speed,
                  const FeasibilityLimits& limits, double gravity, double min_speed) {
  SpeedFit fit;
  fit.requested_speed = requested_speed;
  Trajectory at_request = generate(requested_speed);
  fit.requested = checkFeasibility(at_request, limits, gravity);
  if (fit.requested.feasible()) {
    fit.feasible_speed = requested_speed;
    fit.trajectory = std::move(at_request);
    return fit;
  }
  if (!checkFeasibility(generate(min_speed), limits, gravity).feasible()) return fit;
  double low = min_speed, high = requested_speed;
  while (high - low > 1e-3 * high) {  // the speed to 0.1 %
    const double mid = 0.5 * (low + high);
    (checkFeasibility(generate(mid), limits, gravity).feasible() ? low : high) = mid;
  }
  fit.feasible_speed = low;
  fit.trajectory = generate(low);
  return fit;
}

std::string describeFit(const SpeedFit& fit, const FeasibilityLimits& limits) {
  const FeasibilityReport& r = fit.requested;
  char text[320];
  std::snprintf(text, sizeof text, "at %.3g m/s the path is %s", fit.requested_speed,
                r.feasible() ? "feasible" : "beyond the vehicle:");
  std::string line = text;
  const auto fail = [&](bool ok, const char* what, double value, const char* relation, double limit, const char* unit) {
    if (ok) return;
    std::snprintf(text, sizeof text, " %s %.3g %s %.3g %s;", what, value, relation, limit, unit);
    line += text;
  };
  fail(r.speed_ok, "max speed", r.max_speed, ">", limits.v_max, "m/s");
  fail(r.max_thrust_ok, "max thrust", r.max_thrust, ">", limits.c_max, "m/s^2");
  fail(r.min_thrust_ok, "min thrust", r.min_thrust, "<", limits.c_min, "m/s^2");
  fail(r.body_rate_ok, "max |omega|", r.max_body_rate, ">", limits.omega_max, "rad/s");
  fail(r.consistency_ok, "accel mismatch", r.max_accel_mismatch, ">", limits.accel_mismatch_max, "m/s^2");
  if (r.feasible()) return line;
  if (fit.feasible_speed > 0.0) {
    std::snprintf(text, sizeof text, " feasible up to %.3g m/s", fit.feasible_speed);
  } else {
    std::snprintf(text, sizeof text, " not feasible at any speed");
  }
  return line + text;
}

}  // namespace sdlqr::trajectory
