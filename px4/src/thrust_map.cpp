#include "sdlqr/px4/thrust_map.hpp"

#include <algorithm>
#include <cmath>

#include "thrust_map_rows.hpp"

namespace sdlqr::px4 {

ThrustMap::ThrustMap() { declaration().setDefaults(*this); }

const ParamTable<ThrustMap>& ThrustMap::declaration() {
  static const ParamTable<ThrustMap> table = thrustMapRows();
  return table;
}

double relativeThrust(double normalized, double curve) {
  return (1.0 - curve) * normalized + curve * normalized * normalized;
}

namespace {
// f^-1 on [0, 1]: the root of k T^2 + (1 - k) T - f = 0 in [0, 1].
double inverseRelative(double f, double curve) {
  if (curve < 1e-9) return f;
  const double b = 1.0 - curve;
  return (-b + std::sqrt(b * b + 4.0 * curve * f)) / (2.0 * curve);
}
}  // namespace

double normalizedThrust(double c, const ThrustMap& map, double g) {
  const double f = std::clamp(c / g * relativeThrust(map.hover_throttle, map.curve), 0.0, 1.0);
  return std::clamp(inverseRelative(f, map.curve), 0.0, 1.0);
}

double massNormalizedThrust(double normalized, const ThrustMap& map, double g) {
  return g * relativeThrust(std::clamp(normalized, 0.0, 1.0), map.curve) / relativeThrust(map.hover_throttle, map.curve);
}

HoverFit fitHoverThrottle(const std::vector<HoverSample>& samples, double curve, double g) {
  HoverFit fit;
  double xy = 0.0, xx = 0.0;
  for (const HoverSample& s : samples) {
    const double x = g * relativeThrust(s.normalized_thrust, curve) * std::cos(s.tilt);
    const double y = s.vertical_acceleration + g;
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    xy += x * y;
    xx += x * x;
    ++fit.samples;
  }
  if (fit.samples < 10 || xy <= 0.0) {
    fit.hover_throttle = std::nan("");
    fit.error = "too few hover samples with thrust (" + std::to_string(fit.samples) + ")";
    return fit;
  }
  const double inverse_f = xy / xx;  // 1 / f(h)
  double sum = 0.0;
  for (const HoverSample& s : samples) {
    const double r = s.vertical_acceleration + g - g * relativeThrust(s.normalized_thrust, curve) * std::cos(s.tilt) * inverse_f;
    if (std::isfinite(r)) sum += r * r;
  }
  fit.residual_rms = std::sqrt(sum / fit.samples);
  fit.hover_throttle = inverseRelative(1.0 / inverse_f, curve);
  if (!(fit.hover_throttle > 0.0 && fit.hover_throttle < 1.0)) fit.error = "the fit lies outside (0, 1)";
  return fit;
}

}  // namespace sdlqr::px4
