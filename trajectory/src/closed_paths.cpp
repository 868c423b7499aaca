#include "sdlqr/trajectory/closed_paths.hpp"

#include <cmath>
#include <stdexcept>

#include "sdlqr/trajectory/sampling.hpp"

namespace sdlqr::trajectory {

namespace {

// Phase rate [rad/s] that puts the peak speed at spec.speed.
double phaseRate(const ClosedPathSpec& spec) {
  const double peak_per_rate = spec.shape == ClosedPathShape::kCircle ? spec.size : spec.size * std::sqrt(2.0);
  return spec.speed / peak_per_rate;
}

}  // namespace

std::string closedPathInvalidReason(const ClosedPathSpec& spec) {
  if (!(spec.speed > 0.0 && spec.speed <= 30.0)) return "speed: must be in (0, 30] m/s";
  if (!(spec.size > 0.0 && spec.size <= 100.0)) return "size: must be in (0, 100] m";
  if (!(spec.sample_dt >= 0.001 && spec.sample_dt <= 1.0)) return "sample_dt: must be in [0.001, 1] s";
  if (!spec.center.allFinite()) return "center: must be finite";
  if (!std::isfinite(spec.yaw)) return "yaw: must be finite";
  if (closedPathPeriod(spec) / spec.sample_dt < 8.0) return "sample_dt: fewer than 8 samples per lap";
  return {};
}

double closedPathPeriod(const ClosedPathSpec& spec) { return 2.0 * M_PI / phaseRate(spec); }

FlatOutput closedPathAt(const ClosedPathSpec& spec, double t) {
  const double w = phaseRate(spec), th = w * t, r = spec.size;
  const double s = std::sin(th), c = std::cos(th);
  // d^k p / d theta^k, then times w^k.
  Vec3 d0, d1, d2, d3, d4;
  if (spec.shape == ClosedPathShape::kCircle) {
    d0 = r * Vec3(c, s, 0);
    d1 = r * Vec3(-s, c, 0);
    d2 = r * Vec3(-c, -s, 0);
    d3 = r * Vec3(s, -c, 0);
    d4 = r * Vec3(c, s, 0);
  } else {
    const double s2 = std::sin(2.0 * th), c2 = std::cos(2.0 * th);  // y = (a / 2) sin 2 theta
    d0 = r * Vec3(s, 0.5 * s2, 0);
    d1 = r * Vec3(c, c2, 0);
    d2 = r * Vec3(-s, -2.0 * s2, 0);
    d3 = r * Vec3(-c, -4.0 * c2, 0);
    d4 = r * Vec3(s, 8.0 * s2, 0);
  }
  FlatOutput f;
  f.t = t;
  f.position = spec.center + d0;
  f.velocity = w * d1;
  f.acceleration = w * w * d2;
  f.jerk = w * w * w * d3;
  f.snap = w * w * w * w * d4;
  f.yaw = spec.yaw;
  return f;
}

Trajectory sampleClosedPath(const ClosedPathSpec& spec, double gravity) {
  if (const std::string why = closedPathInvalidReason(spec); !why.empty()) throw std::invalid_argument(why);
  const double period = closedPathPeriod(spec);
  const long intervals = std::lround(std::ceil(period / spec.sample_dt - 1e-9));
  Trajectory out;
  out.closed = true;
  for (long k = 0; k <= intervals; ++k) {
    // The last sample is the first again, exactly: the lap closes on it.
    const double t = k == intervals ? period : static_cast<double>(k) * period / static_cast<double>(intervals);
    appendSample(out, t, flatToReference(closedPathAt(spec, k == intervals ? 0.0 : t), gravity));
  }
  return out;
}

}  // namespace sdlqr::trajectory
