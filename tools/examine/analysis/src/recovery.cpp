#include "sdlqr/analysis/recovery.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "flight_parts.hpp"
#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::analysis {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using detail::seconds;

// First time of a command of `type` at or after t [s]; NaN when none.
double firstCommand(const logger::FlightLog& log, CommandType type, double t) {
  for (const Command& c : log.command.messages) {
    if (c.command == type && seconds(c.utime) >= t) return seconds(c.utime);
  }
  return kNaN;
}

// Time after `start` from which `ok` holds on every truth sample up to `end` (NaN: never).
template <class Ok>
double holdsFrom(const logger::FlightLog& log, double start, double end, Ok ok) {
  double since = kNaN;
  for (const SimTruth& s : log.sim_truth.messages) {
    const double t = seconds(s.utime);
    if (t < start || t > end) continue;
    if (!ok(s)) since = kNaN;
    else if (!std::isfinite(since)) since = t;
  }
  return std::isfinite(since) ? since - start : kNaN;
}

}  // namespace

std::optional<RecoveryReport> analyzeRecovery(const logger::FlightLog& log, const mission::Scenario& scenario,
                                              const RecoveryOptions& options) {
  const bool throw_start = scenario.sim.throw_event.enabled();
  if (!throw_start && !scenario.sim.airborne_start.enabled()) return std::nullopt;
  RecoveryReport r;
  r.throw_start = throw_start;
  r.release = throw_start ? scenario.sim.throw_event.releaseTime() : 0.0;
  r.start = throw_start ? firstCommand(log, CommandType::kArm, r.release) : 0.0;
  r.detect_delay = throw_start ? r.start - r.release : kNaN;
  r.level_time = r.height_lost = r.settle_time = kNaN;
  if (!std::isfinite(r.start) || log.sim_truth.size() == 0) return r;
  const double land = firstCommand(log, CommandType::kLand, r.start);
  const double end = std::isfinite(land) ? land : std::numeric_limits<double>::infinity();

  const double level = options.level_tilt_deg * M_PI / 180.0;
  // On the ground is neither level nor settled: the ground puts a fallen vehicle level.
  r.level_time = holdsFrom(log, r.start, end,
                           [&](const SimTruth& s) { return !s.on_ground && quat::tilt(s.orientation) <= level; });
  // The hold it ends in: the last reference before the landing (or the end of the log).
  const auto last = log.reference.indexAtOrBefore(std::isfinite(land) ? std::llround(land * 1e6) - 1
                                                                     : std::numeric_limits<int64_t>::max());
  if (last >= 0) {
    const Vec3 hold = position(log.reference[static_cast<size_t>(last)].x);
    r.settle_time = holdsFrom(log, r.start, end, [&](const SimTruth& s) {
      return !s.on_ground && (s.position - hold).norm() <= options.settle_error;
    });
  }
  double start_z = kNaN, lowest = std::numeric_limits<double>::infinity();
  for (const SimTruth& s : log.sim_truth.messages) {
    const double t = seconds(s.utime);
    if (t < r.start || t > end) continue;
    if (!std::isfinite(start_z)) {
      start_z = s.position[2];
      r.initial_tilt_deg = quat::tilt(s.orientation) * 180.0 / M_PI;
    }
    lowest = std::min(lowest, s.position[2]);
  }
  if (std::isfinite(start_z)) r.height_lost = std::max(0.0, start_z - lowest);
  return r;
}

}  // namespace sdlqr::analysis
