#include "sdlqr/px4/hover_identification.hpp"

#include <cmath>
#include <cstdio>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::px4 {

std::vector<HoverSample> hoverSamples(const logger::FlightLog& log, const ThrustMap& flown, double gravity) {
  std::vector<HoverSample> samples;
  const auto& estimates = log.state_estimate;
  if (estimates.size() < 3) return samples;
  const double ground_z = estimates[0].position[2];
  for (const RateCommand& command : log.rate_command.messages) {
    const std::ptrdiff_t i = estimates.indexAtOrBefore(command.utime);
    if (i < 1 || static_cast<size_t>(i) + 5 >= estimates.size()) continue;
    const StateEstimate& before = estimates[static_cast<size_t>(i - 1)];
    const StateEstimate& after = estimates[static_cast<size_t>(i) + 5];  // ~20 ms later at 250 Hz
    const StateEstimate& now = estimates[static_cast<size_t>(i)];
    const double dt = 1e-6 * static_cast<double>(after.utime - before.utime);
    if (!(dt > 0.0 && dt < 0.1)) continue;
    const double tilt = quat::tilt(now.orientation);
    if (std::abs(now.velocity[2]) > 0.3 || tilt > 10.0 * M_PI / 180.0 || now.position[2] < ground_z + 0.3) continue;
    HoverSample s;
    s.normalized_thrust = normalizedThrust(command.thrust, flown, gravity);
    s.vertical_acceleration = (after.velocity[2] - before.velocity[2]) / dt;
    s.tilt = tilt;
    samples.push_back(s);
  }
  return samples;
}

int identifyHover(const std::string& log_path, const BridgeParams& flown, double gravity, std::ostream& out) {
  const logger::FlightLog log = logger::FlightLog::load(log_path);
  const HoverFit fit = fitHoverThrottle(hoverSamples(log, flown.thrust, gravity), flown.thrust.curve, gravity);
  if (!fit.error.empty()) {
    out << "no hover throttle from " << log_path << ": " << fit.error << "\n";
    return 1;
  }
  char text[256];
  std::snprintf(text, sizeof text,
                "px4.thrust.hover_throttle: %.4f  # fitted to %d near-hover samples (residual %.2f m/s^2 RMS); "
                "flown with %.4f, curve %.2f\n",
                fit.hover_throttle, fit.samples, fit.residual_rms, flown.thrust.hover_throttle, flown.thrust.curve);
  out << text;
  return 0;
}

}  // namespace sdlqr::px4
