#include "sdlqr/analysis/flight_report.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include "flight_parts.hpp"
#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/analysis/trajectory_aborts.hpp"
#include "sdlqr/config/config.hpp"

namespace sdlqr::analysis {

namespace {

// Trajectory tracking, labelled by the scenario's trajectory events in order.
std::vector<PathTrackingReport> trackTrajectories(const logger::FlightLog& log, const mission::Scenario& scenario,
                                                  PathTrackingOptions options) {
  options.skip_radius = scenario.criterion("skip_radius", options.skip_radius);
  options.skip_window = scenario.criterion("skip_window", options.skip_window);
  options.return_error = scenario.criterion("path_return_error", options.return_error);
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
  return std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.pass; });
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
  detail::summarizeTruth(log, report);
  detail::analyzeWindows(log, scenario, options, report);
  report.estimator = detail::estimatorAccuracy(log);
  detail::measureTiming(log, options, report);
  if (std::isfinite(report.flight_start)) {
    report.saturation = detail::measureSaturation(log, options, report.flight_start, report.flight_end);
  }
  detail::measureLoad(log, report);
  report.message_loss = detail::measureMessageLoss(log);
  report.trajectories = trackTrajectories(log, scenario, options.path);
  RecoveryOptions recovery;
  recovery.level_tilt_deg = scenario.criterion("recovery_level_tilt_deg", recovery.level_tilt_deg);
  recovery.settle_error = scenario.criterion("recovery_settle_error", recovery.settle_error);
  report.recovery = analyzeRecovery(log, scenario, recovery);
  report.trajectory_aborts = countTrajectoryAborts(log);
  judgeCriteria(report, scenario, options);
  return report;
}

}  // namespace sdlqr::analysis
