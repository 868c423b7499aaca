#include "sdlqr/trajectory/sampling.hpp"

#include <cmath>
#include <stdexcept>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::trajectory {

void appendSample(Trajectory& out, double t, const FlatReference& reference) {
  TrajectorySample sample;
  sample.t = t;
  sample.x = reference.x;
  sample.u = reference.u;
  if (!out.samples.empty()) {
    orientation(sample.x) = quat::sameHemisphere(orientation(sample.x), orientation(out.samples.back().x));
  }
  out.samples.push_back(sample);
}

Trajectory sampleTrajectory(const MinSnapTrajectory& polynomial, double dt, double gravity) {
  if (!std::isfinite(dt) || dt <= 0.0) throw std::invalid_argument("sample dt must be finite and > 0");
  const double duration = polynomial.duration();
  // A final interval shorter than this would only repeat the last sample.
  const double too_close = 1e-6 * dt;
  Trajectory out;
  out.closed = polynomial.periodic;
  auto add = [&](double t) { appendSample(out, t, flatToReference(polynomial.evaluate(t), gravity)); };
  for (long k = 0;; ++k) {
    const double t = static_cast<double>(k) * dt;
    if (t > duration - too_close) break;
    add(t);
  }
  add(duration);
  return out;
}

}  // namespace sdlqr::trajectory
