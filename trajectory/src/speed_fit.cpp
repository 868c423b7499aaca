#include "sdlqr/trajectory/speed_fit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/flatness.hpp"
#include "sdlqr/trajectory/transition.hpp"

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

Trajectory timeScaled(const Trajectory& trajectory, double factor, double gravity) {
  Trajectory out = trajectory;
  const auto& in = trajectory.samples;
  const size_t n = in.size();
  for (size_t k = 0; k < n; ++k) {
    // Thrust and heading rates by central differences (one-sided at the ends).
    const size_t a = k > 0 ? k - 1 : k, b = k + 1 < n ? k + 1 : k;
    const double span = b > a ? in[b].t - in[a].t : 0.0;
    const double thrust_rate = span > 0.0 ? (in[b].u[kThrust] - in[a].u[kThrust]) / span : 0.0;
    const double yaw_change = std::remainder(quat::yaw(orientation(in[b].x)) - quat::yaw(orientation(in[a].x)), 2.0 * M_PI);
    const FlatState s = flatStateOf(in[k].x, in[k].u, thrust_rate, gravity);
    FlatOutput f;
    f.t = in[k].t / factor;
    f.position = s.position;
    f.velocity = factor * s.velocity;
    f.acceleration = factor * factor * s.acceleration;
    f.jerk = factor * factor * factor * s.jerk;
    f.yaw = s.yaw;
    f.yaw_rate = span > 0.0 ? factor * yaw_change / span : 0.0;
    const FlatReference ref = flatToReference(f, gravity);
    out.samples[k].t = f.t;
    out.samples[k].x = ref.x;
    out.samples[k].u = ref.u;
  }
  return out;
}

double peakSpeed(const Trajectory& trajectory) {
  double peak = 0.0;
  for (const TrajectorySample& s : trajectory.samples) peak = std::max(peak, velocity(s.x).norm());
  return peak;
}

std::function<Trajectory(double)> givenPathAtSpeed(Trajectory as_given, double gravity) {
  const double peak = peakSpeed(as_given);
  return [as_given = std::move(as_given), peak, gravity](double speed) {
    return speed == peak || !(peak > 0.0) ? as_given : timeScaled(as_given, speed / peak, gravity);
  };
}

std::string describeFit(const SpeedFit& fit, const FeasibilityLimits& limits) {
  const FeasibilityReport& r = fit.requested;
  char text[320];
  std::snprintf(text, sizeof text, "at %.3g m/s the path is %s", fit.requested_speed,
                r.feasible() ? "feasible" : "beyond the vehicle:");
  std::string line = text;
  line += describeViolations(r, limits);
  if (r.feasible()) return line;
  if (fit.feasible_speed > 0.0) {
    std::snprintf(text, sizeof text, " feasible up to %.3g m/s", fit.feasible_speed);
  } else {
    std::snprintf(text, sizeof text, " not feasible at any speed");
  }
  return line + text;
}

}  // namespace sdlqr::trajectory
