#include "sdlqr/compare/compare_metrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "sdlqr/batch/flight.hpp"

namespace sdlqr::compare {

namespace {

using analysis::FlightReport;
using analysis::PathTrackingReport;
using analysis::RecoveryReport;
using analysis::SetpointWindow;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

batch::Metric batchMetric(const char* name) {
  for (const batch::Metric& m : batch::flightMetrics()) {
    if (std::string(m.name) == name) return m;
  }
  throw std::logic_error(std::string("no batch metric ") + name);
}

// A recovery figure: NaN without a recovery, +inf when it has one and the figure was never reached.
double ofRecovery(const FlightReport& r, double RecoveryReport::*field) {
  if (!r.recovery) return kNaN;
  const double v = (*r.recovery).*field;
  return std::isnan(v) ? std::numeric_limits<double>::infinity() : v;
}

double jumpOvershootPercent(const FlightReport& r) {
  std::vector<SetpointWindow> jumps;
  for (const SetpointWindow& w : r.setpoints) {
    if (w.is_jump) jumps.push_back(w);
  }
  return 100.0 * batch::largestOf(jumps, [](const SetpointWindow& w) { return w.overshoot; });
}

double pathReturnTime(const FlightReport& r) {
  double worst = kNaN;
  for (const PathTrackingReport& t : r.trajectories) {
    const double v = batch::largestOf(t.pulls, [](const analysis::PathPull& p) { return p.return_time; });
    if (!std::isnan(v)) worst = std::isnan(worst) ? v : std::max(worst, v);
  }
  return worst;
}

// Counts over the airborne flight; NaN when nothing was counted (no MOTOR_CMD recorded or never airborne).
double countOf(int64_t count, int64_t of) { return of > 0 ? static_cast<double>(count) : kNaN; }

std::vector<batch::Metric> makeMetrics() {
  return {
      batchMetric("path_error_rms_max"),
      {"path_error_max", "m",
       [](const FlightReport& r) {
         return batch::largestOf(r.trajectories, [](const PathTrackingReport& t) { return t.path_error_max; });
       }},
      {"skipped_samples", "count",
       [](const FlightReport& r) {
         return batch::largestOf(r.trajectories, [](const PathTrackingReport& t) { return double(t.skipped.size()); });
       }},
      {"path_return_time", "s", pathReturnTime},
      {"trajectory_aborts", "count",  // by the controller's guard, of flights that tracked a trajectory
       [](const FlightReport& r) { return r.trajectories.empty() ? kNaN : static_cast<double>(r.trajectory_aborts); }},
      batchMetric("jump_settle_time_max"),
      {"jump_overshoot_max", "%", jumpOvershootPercent},
      batchMetric("hover_error_max"),
      {"pull_return_time_max", "s",
       [](const FlightReport& r) {
         return batch::largestOf(r.pulls, [](const analysis::PullWindow& p) { return p.return_time; });
       }},
      {"throw_detect_delay", "s",
       [](const FlightReport& r) {
         return r.recovery && r.recovery->throw_start ? ofRecovery(r, &RecoveryReport::detect_delay) : kNaN;
       }},
      {"recovery_level_time", "s", [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::level_time); }},
      {"recovery_height_lost", "m", [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::height_lost); }},
      {"recovery_settle_time", "s", [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::settle_time); }},
      batchMetric("max_tilt_deg"),
      {"thrust_demand_outside", "count",
       [](const FlightReport& r) { return countOf(r.saturation.thrust_demand_outside, r.saturation.commands); }},
      {"rotor_at_limit", "count",
       [](const FlightReport& r) { return countOf(r.saturation.rotor_at_limit, r.saturation.motor_commands); }},
  };
}

}  // namespace

const std::vector<batch::Metric>& compareMetrics() {
  static const std::vector<batch::Metric> metrics = makeMetrics();
  return metrics;
}

}  // namespace sdlqr::compare
