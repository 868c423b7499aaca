#include "sdlqr/analysis/flight_report.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "flight_parts.hpp"
#include "sdlqr/analysis/criteria.hpp"

namespace sdlqr::analysis {

namespace {

// Trajectory tracking, labelled by the scenario's trajectory events in order.
std::vector<PathTrackingReport> trackTrajectories(const logger::FlightLog& log, const mission::Scenario& scenario,
                                                  PathTrackingOptions options) {
  options.skip_radius = scenario.criterion("skip_radius", options.skip_radius);
  options.skip_window = scenario.criterion("skip_window", options.skip_window);
  options.return_error = scenario.criterion("path_return_error", options.return_error);
  if (scenario.criteria.count("thrust_limit_violations_max") &&
      !(std::isfinite(options.thrust_min) && std::isfinite(options.thrust_max))) {
    throw std::invalid_argument("criteria.thrust_limit_violations_max: needs the vehicle's thrust limits");
  }
  std::vector<PathTrackingReport> reports = analyzePathTracking(log, options);
  std::vector<std::string> labels;
  for (const mission::ScenarioEvent& s : scenario.events) {
    if (s.kind == mission::ScenarioEvent::Kind::kTrajectory) labels.push_back(s.label);
  }
  for (size_t i = 0; i < reports.size(); ++i) {
    PathTrackingReport& t = reports[i];
    t.label = i < labels.size() && !labels[i].empty() ? labels[i] : "trajectory " + std::to_string(i + 1);
  }
  return reports;
}

}  // namespace

bool FlightReport::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.pass; });
}

FlightReport analyzeFlight(const logger::FlightLog& log, const mission::Scenario& scenario, AnalysisOptions options) {
  checkCriteriaKeys(scenario);
  FlightReport report;
  report.scenario = scenario.name;
  report.calibration = options.calibration;
  detail::summarizeTruth(log, report);
  detail::analyzeWindows(log, scenario, options, report);
  report.estimator = detail::estimatorAccuracy(log);
  detail::measureTiming(log, options, report);
  detail::measureLoad(log, report);
  report.message_loss = detail::measureMessageLoss(log);
  report.trajectories = trackTrajectories(log, scenario, options.path);
  judgeCriteria(report, scenario, options);
  return report;
}

}  // namespace sdlqr::analysis
