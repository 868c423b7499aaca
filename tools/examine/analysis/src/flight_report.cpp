#include "sdlqr/analysis/flight_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "flight_parts.hpp"
#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/analysis/trajectory_aborts.hpp"
#include "sdlqr/config/config.hpp"

namespace sdlqr::analysis {

namespace {

const PathTrackingReport* reportOf(const std::vector<PathTrackingReport>& reports, int64_t seq, double start) {
  for (const PathTrackingReport& r : reports) {
    // r.start is where an entry handed over to the path (entry_time after the upload).
    if (r.trajectory_seq == seq && std::abs(r.start - r.entry_time - start) < 1e-6) return &r;
  }
  return nullptr;
}

// A trajectory of the scenario without figures: not in the log, or never tracked.
PathTrackingReport untracked(const ExpectedEvent& x, std::string why) {
  PathTrackingReport r;
  r.label = x.label;
  r.start = r.end = x.found() ? x.seen : x.at;
  r.missing = std::move(why);
  return r;
}

// The path pulls of one trajectory labelled by the scenario's pulls played on it; a pull of the
// scenario that is not among them (not in the log, or after the trajectory's window) is added
// without figures, and one that is not the scenario's is named by its time.
void labelPathPulls(PathTrackingReport& r, const std::vector<const ExpectedEvent*>& pulls) {
  std::vector<PathPull> labelled;
  std::vector<bool> used(r.pulls.size(), false);
  for (const ExpectedEvent* x : pulls) {
    PathPull p;
    p.label = x->label;
    p.start = p.release = x->found() ? x->seen : x->at;
    p.missing = x->describe();
    for (size_t i = 0; i < r.pulls.size(); ++i) {
      if (used[i] || !x->found() || std::abs(r.pulls[i].start - x->seen) > 1e-6) continue;
      p = r.pulls[i];
      p.label = x->label;
      used[i] = true;
      break;
    }
    if (x->found() && !p.missing.empty()) {
      char why[128];
      std::snprintf(why, sizeof why, ", after the trajectory was tracked (until %.1f s)", r.end);
      p.missing += why;
    }
    labelled.push_back(p);
  }
  for (size_t i = 0; i < r.pulls.size(); ++i) {
    if (used[i]) continue;
    char label[64];
    std::snprintf(label, sizeof label, "pull at %.1f s", r.pulls[i].start);
    labelled.push_back(r.pulls[i]);
    labelled.back().label = label;
  }
  r.pulls = std::move(labelled);
}

// Trajectory tracking of each trajectory the scenario plays, then of any other the controller
// tracked (a foreign upload), each with the scenario's pulls played on it.
std::vector<PathTrackingReport> trackTrajectories(const logger::FlightLog& log, const mission::Scenario& scenario,
                                                  const std::vector<ExpectedEvent>& events, PathTrackingOptions options) {
  options.skip_radius = scenario.criterion("skip_radius", options.skip_radius);
  options.skip_window = scenario.criterion("skip_window", options.skip_window);
  options.return_error = scenario.criterion("path_return_error", options.return_error);
  const std::vector<PathTrackingReport> tracked = analyzePathTracking(log, options);
  std::vector<PathTrackingReport> reports;
  std::vector<const PathTrackingReport*> used;
  std::vector<std::vector<const ExpectedEvent*>> pulls;
  for (const ExpectedEvent& x : events) {
    if (x.kind == ExpectedEvent::Kind::kPull && x.on_trajectory && !pulls.empty()) pulls.back().push_back(&x);
    if (x.kind != ExpectedEvent::Kind::kTrajectory) continue;
    pulls.emplace_back();
    if (!x.found()) {
      reports.push_back(untracked(x, x.describe()));
      continue;
    }
    const PathTrackingReport* r = reportOf(tracked, log.trajectory[static_cast<size_t>(x.message)].seq, x.seen);
    if (r == nullptr) {
      char aborted[96] = "";
      const double at = trajectoryAbortTime(log, log.trajectory[static_cast<size_t>(x.message)].seq);
      if (std::isfinite(at)) std::snprintf(aborted, sizeof aborted, " (the guard aborted its entry into a hold at %.2f s)", at);
      reports.push_back(untracked(x, x.describe() + ", never tracked by the controller" + aborted));
      continue;
    }
    used.push_back(r);
    reports.push_back(*r);
    reports.back().label = x.label;
  }
  for (size_t i = 0; i < reports.size(); ++i) labelPathPulls(reports[i], pulls[i]);
  for (const PathTrackingReport& r : tracked) {
    if (std::find(used.begin(), used.end(), &r) != used.end()) continue;
    reports.push_back(r);
    reports.back().label = "TRAJECTORY seq " + std::to_string(r.trajectory_seq) + " (not in the scenario)";
    labelPathPulls(reports.back(), {});
  }
  return reports;
}

// A saturation criterion without the vehicle's limits would compare against +-infinity and pass.
void requireLimits(const mission::Scenario& scenario, const AnalysisOptions& options) {
  const bool thrust = std::isfinite(options.path.thrust_min) && std::isfinite(options.path.thrust_max);
  const bool rotors = std::isfinite(options.rotor_thrust_min) && std::isfinite(options.rotor_thrust_max);
  for (const auto& [key, needs] : {std::pair<const char*, bool>{"thrust_limit_violations_max", thrust},
                                   {"thrust_demand_outside_max", thrust},
                                   {"rotor_at_limit_max", rotors}}) {
    if (scenario.criteria.count(key) && !needs) {
      throw std::invalid_argument(std::string("criteria.") + key + ": needs the vehicle's limits (setVehicleLimits)");
    }
  }
}

}  // namespace

void setVehicleLimits(AnalysisOptions& options, const LqrParams& lqr, const VehicleParams& vehicle) {
  options.path.thrust_min = lqr.c_min;
  options.path.thrust_max = lqr.c_max;
  options.rotor_thrust_min = vehicle.min_rotor_thrust;
  options.rotor_thrust_max = vehicle.max_rotor_thrust;
}

bool FlightReport::passed() const {
  return !checks.empty() && std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.pass; });
}

FlightReport analyzeFlight(const logger::FlightLog& log, const mission::Scenario& scenario, AnalysisOptions options) {
  checkCriteriaKeys(scenario);
  const bool limits_given = std::isfinite(options.path.thrust_min) || std::isfinite(options.rotor_thrust_min);
  if (!limits_given && !scenario.vehicle_path.empty()) {
    const ConfigReader vehicle = loadVehicleConfig(scenario.vehicle_path);
    setVehicleLimits(options, LqrParams::load(vehicle.child("lqr")), VehicleParams::load(vehicle.child("vehicle")));
  }
  requireLimits(scenario, options);
  FlightReport report;
  report.scenario = scenario.name;
  report.calibration = options.calibration;
  report.events = expectedEvents(scenario);
  findInLog(report.events, log);
  detail::summarizeTruth(log, report);
  detail::analyzeWindows(log, options, report, scenario);
  detail::analyzeLandings(log, report);
  report.estimator = detail::estimatorAccuracy(log);
  detail::measureTiming(log, options, report);
  if (std::isfinite(report.flight_start)) {
    report.saturation = detail::measureSaturation(log, options, report.flight_start, report.flight_end);
  }
  detail::measureLoad(log, report);
  report.message_loss = detail::measureMessageLoss(log);
  report.trajectories = trackTrajectories(log, scenario, report.events, options.path);
  RecoveryOptions recovery;
  recovery.level_tilt_deg = scenario.criterion("recovery_level_tilt_deg", recovery.level_tilt_deg);
  recovery.settle_error = scenario.criterion("recovery_settle_error", recovery.settle_error);
  report.recovery = analyzeRecovery(log, scenario, recovery);
  report.trajectory_aborts = countTrajectoryAborts(log);
  judgeCriteria(report, scenario, options);
  return report;
}

}  // namespace sdlqr::analysis
