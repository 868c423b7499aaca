#include "sdlqr/analysis/criteria.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace sdlqr::analysis {

namespace {

using S = Scope;
using B = Bound;

// What a criterion is called and says, and what it bounds; the caller sets the value of its scope.
CriterionSpec described(std::string_view key, B bound, S scope, std::string_view unit, std::string_view description) {
  CriterionSpec c;
  c.key = key;
  c.bound = bound;
  c.unit = unit;
  c.description = description;
  c.scope = scope;
  return c;
}

// A criterion of `scope` whose value `of` reads, kept in the spec's `value` member of that scope.
// `of` is not deduced (common_type), so a lambda converts to the member's function pointer.
template <typename Of>
CriterionSpec valued(std::string_view key, B bound, S scope, std::string_view unit, std::string_view description,
                     Of CriterionSpec::*value, typename std::common_type<Of>::type of) {
  CriterionSpec c = described(key, bound, scope, unit, description);
  c.*value = of;
  return c;
}

CriterionSpec flight(std::string_view key, B bound, std::string_view unit, std::string_view description,
                     double (*of)(const FlightReport&)) {
  return valued(key, bound, S::kFlight, unit, description, &CriterionSpec::of_flight, of);
}

// A count among `of` messages; not a number (a failed check) when there were none to count.
double countOf(int64_t count, int64_t of) { return of > 0 ? static_cast<double>(count) : kNotReached; }

CriterionSpec relative(CriterionSpec c) {
  c.needs_calibration = true;
  c.needs_heartbeats = true;
  return c;
}

CriterionSpec setpoint(std::string_view key, S scope, std::string_view unit, std::string_view description,
                       double (*of)(const SetpointWindow&)) {
  return valued(key, B::kAtMost, scope, unit, description, &CriterionSpec::of_setpoint, of);
}

CriterionSpec trajectory(std::string_view key, B bound, std::string_view unit, std::string_view description,
                         double (*of)(const PathTrackingReport&)) {
  return valued(key, bound, S::kTrajectory, unit, description, &CriterionSpec::of_trajectory, of);
}

// Recoveries from an airborne start or a throw (recovery.hpp): NaN, a failed check, without one.
double ofRecovery(const FlightReport& r, double RecoveryReport::*field) {
  return r.recovery ? (*r.recovery).*field : kNotReached;
}

void addRecoveryCriteria(std::vector<CriterionSpec>& c) {
  c.push_back(flight("recovery_level_time", B::kAtMost, "s", "tilt below {recovery_level_tilt_deg} for good, after the start",
                     [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::level_time); }));
  c.push_back(flight("recovery_height_lost", B::kAtMost, "m", "height at the start minus the lowest after it",
                     [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::height_lost); }));
  c.push_back(flight("recovery_settle_time", B::kAtMost, "s", "within {recovery_settle_error} of the reference for good",
                     [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::settle_time); }));
  c.push_back(flight("trajectory_aborts_max", B::kAtMost, "count", "trajectories the guard aborted into a hold",
                     [](const FlightReport& r) { return static_cast<double>(r.trajectory_aborts); }));
  c.push_back(flight("trajectory_aborts_min", B::kAtLeast, "count", "trajectories the guard aborted into a hold",
                     [](const FlightReport& r) { return static_cast<double>(r.trajectory_aborts); }));
  c.push_back(flight("throw_detect_delay", B::kAtMost, "s", "throw detected (ARM) after the hand let go",
                     [](const FlightReport& r) { return ofRecovery(r, &RecoveryReport::detect_delay); }));
}

CriterionSpec always(CriterionSpec c, double default_limit) {
  c.always = true;
  c.default_limit = default_limit;
  return c;
}

// Judged on every flight whether the scenario names them or not.
void addAlwaysCriteria(std::vector<CriterionSpec>& c) {
  c.push_back(always(flight("nonfinite_messages", B::kAtMost, "count", "messages with NaN or Inf (estimates, commands, gains)",
                            [](const FlightReport& r) { return static_cast<double>(r.nonfinite); }), 0.0));
  c.push_back(always(flight("crashed", B::kAtMost, "-", "vehicle crashed (1) or not (0)",
                            [](const FlightReport& r) { return r.crashed ? 1.0 : 0.0; }), 0.0));
  // Every event of the scenario (scenario_events.hpp): what it played reached the log.
  c.push_back(always(valued("event_in_log", B::kAtLeast, S::kEvent, "-",
                            "the scenario event's message in the log (1) or not (0)", &CriterionSpec::of_event,
                            [](const ExpectedEvent& e) { return e.found() ? 1.0 : 0.0; }),
                     1.0));
}

// Setpoints, jumps (Fig. 5) and pulls while holding a setpoint (Fig. 4).
void addSetpointCriteria(std::vector<CriterionSpec>& c) {
  c.push_back(setpoint("jump_settle_time", S::kJump, "s", "settle time: error below {jump_settle_error} and staying",
                       [](const SetpointWindow& w) { return w.settle_time; }));
  c.push_back(setpoint("jump_max_overshoot", S::kJump, "-", "overshoot along the jump, fraction of its size",
                       [](const SetpointWindow& w) { return w.overshoot; }));
  c.push_back(setpoint("takeoff_settle_time", S::kTakeoff, "s",
                       "after TAKEOFF, within {jump_settle_error} of the commanded height and staying",
                       [](const SetpointWindow& w) { return w.settle_time; }));
  c.push_back(setpoint("hover_error", S::kSetpoint, "m", "steady error, mean over the window's last {hover_window}",
                       [](const SetpointWindow& w) { return w.steady_error; }));
  // Pulls while holding a setpoint (Fig. 4).
  const CriterionSpec pull =
      valued("pull_return_time", B::kAtMost, S::kPull, "s",
             "after release, back within {pull_return_error} of the setpoint and staying", &CriterionSpec::of_pull,
             [](const PullWindow& p) { return p.return_time; });
  c.push_back(pull);
  CriterionSpec pull_overshoot = pull;
  pull_overshoot.key = "pull_return_overshoot";
  pull_overshoot.unit = "-";
  pull_overshoot.description = "after release, travel past the setpoint, fraction of the pull's largest deviation";
  pull_overshoot.of_pull = [](const PullWindow& p) { return p.return_overshoot; };
  c.push_back(pull_overshoot);
}

// Estimator and rates (simulation time), tilt, touchdown and saturation: figures of the whole flight.
void addFlightCriteria(std::vector<CriterionSpec>& c) {
  c.push_back(flight("estimator_position_rms", B::kAtMost, "m", "estimator position error RMS in hover",
                     [](const FlightReport& r) { return r.estimator.position_rms; }));
  c.push_back(flight("estimator_attitude_rms_deg", B::kAtMost, "deg", "estimator attitude error RMS in hover",
                     [](const FlightReport& r) { return r.estimator.attitude_rms_deg; }));
  c.push_back(flight("gains_rate_min", B::kAtLeast, "Hz", "GAINS rate, simulation time",
                     [](const FlightReport& r) { return r.gains_rate_hz; }));
  c.push_back(flight("gains_rate_max", B::kAtMost, "Hz", "GAINS rate, simulation time",
                     [](const FlightReport& r) { return r.gains_rate_hz; }));
  c.push_back(flight("rate_cmd_rate_min", B::kAtLeast, "Hz", "RATE_CMD rate, simulation time",
                     [](const FlightReport& r) { return r.rate_cmd_rate_hz; }));
  c.push_back(flight("rate_cmd_rate_max", B::kAtMost, "Hz", "RATE_CMD rate, simulation time",
                     [](const FlightReport& r) { return r.rate_cmd_rate_hz; }));
  c.push_back(flight("state_est_rate_min", B::kAtLeast, "Hz", "STATE_EST rate, simulation time",
                     [](const FlightReport& r) { return r.state_est_rate_hz; }));
  c.push_back(flight("state_est_rate_max", B::kAtMost, "Hz", "STATE_EST rate, simulation time",
                     [](const FlightReport& r) { return r.state_est_rate_hz; }));
  c.push_back(flight("max_tilt_deg", B::kAtMost, "deg", "largest tilt while airborne",
                     [](const FlightReport& r) { return r.max_tilt_deg; }));
  c.push_back(valued("touchdown_speed_max", B::kAtMost, S::kLanding, "m/s",
                     "after LAND, vertical speed at touchdown (none before the log ends: not landed)",
                     &CriterionSpec::of_landing, [](const Landing& l) { return l.touchdown_speed; }));
  // Saturation where it happens (Saturation in flight_report.hpp), over the airborne flight.
  c.push_back(flight("thrust_demand_outside_max", B::kAtMost, "count",
                     "RATE_CMD whose thrust demand before the controller's clip left [c_min, c_max], or NaN",
                     [](const FlightReport& r) { return countOf(r.saturation.thrust_demand_outside, r.saturation.commands); }));
  c.push_back(flight("rotor_at_limit_max", B::kAtMost, "count",
                     "MOTOR_CMD (rate mode) with a rotor at the mixer's limit (min or max rotor thrust)",
                     [](const FlightReport& r) { return countOf(r.saturation.rotor_at_limit, r.saturation.motor_commands); }));
}

// Machine-dependent figures, judged only against this machine's calibration.
void addRelativeCriteria(std::vector<CriterionSpec>& c) {
  c.push_back(relative(flight("stack_cpu_relative_max", B::kAtMost, "-",
                              "flight-stack CPU over the CPU of a 1 kHz ping/pong on this bus (calibration)",
                              [](const FlightReport& r) { return r.stack_cpu_relative; })));
  c.push_back(relative(flight("state_to_command_latency_relative_max", B::kAtMost, "-",
                              "STATE_EST -> RATE_CMD latency median over the one-way median of the calibration",
                              [](const FlightReport& r) { return r.state_to_command_relative; })));
  // The tails (p99) are reported, never judged: on two cores shared by seven processes they are
  // the scheduler's, which a two-process ping/pong does not see (CI measured 27x and 37x its
  // one-way p99 where this machine measures 5x).
  c.push_back(relative(flight("rate_cmd_wall_jitter_relative_max", B::kAtMost, "-",
                              "RATE_CMD wall-clock period beyond its STATE_EST's, |jitter| median, over the calibration's one-way median",
                              [](const FlightReport& r) { return r.rate_cmd_wall_jitter_relative; })));
}

// Trajectories (path_tracking.hpp).
void addTrajectoryCriteria(std::vector<CriterionSpec>& c) {
  c.push_back(trajectory("path_error_rms", B::kAtMost, "m", "distance to the path, RMS",
                         [](const PathTrackingReport& t) { return t.path_error_rms; }));
  c.push_back(trajectory("path_error_max", B::kAtMost, "m", "distance to the path, max",
                         [](const PathTrackingReport& t) { return t.path_error_max; }));
  c.push_back(trajectory("skipped_samples_max", B::kAtMost, "count", "samples skipped (never within {skip_radius})",
                         [](const PathTrackingReport& t) { return static_cast<double>(t.skipped.size()); }));
  c.push_back(trajectory("skipped_samples_min", B::kAtLeast, "count", "samples skipped (never within {skip_radius})",
                         [](const PathTrackingReport& t) { return static_cast<double>(t.skipped.size()); }));
  c.push_back(trajectory("trajectory_laps_min", B::kAtLeast, "-", "laps flown",
                         [](const PathTrackingReport& t) { return t.laps; }));
  c.push_back(trajectory("trajectory_completed", B::kAtLeast, "-", "reference reached the end of the trajectory (1)",
                         [](const PathTrackingReport& t) { return t.completed ? 1.0 : 0.0; }));
  c.push_back(trajectory("thrust_limit_violations_max", B::kAtMost, "count",
                         "thrust demands (before the controller's clip) outside the vehicle's [c_min, c_max], or NaN",
                         [](const PathTrackingReport& t) { return static_cast<double>(t.thrust_violations); }));
  c.push_back(valued("path_return_time", B::kAtMost, S::kTrajectoryPull, "s",
                     "after release, back within {path_return_error} of the path and staying",
                     &CriterionSpec::of_trajectory_pull, [](const PathPull& p) { return p.return_time; }));
}

// The table's order is the order of the checks in every report.
std::vector<CriterionSpec> makeCriteria() {
  std::vector<CriterionSpec> c;
  addAlwaysCriteria(c);
  addSetpointCriteria(c);
  addFlightCriteria(c);
  addRelativeCriteria(c);
  addTrajectoryCriteria(c);
  addRecoveryCriteria(c);
  return c;
}

double thresholdDefault(std::string_view key, const AnalysisOptions& options) {
  if (key == "jump_settle_error") return options.settle_error;
  if (key == "pull_return_error") return options.return_error;
  if (key == "skip_radius") return options.path.skip_radius;
  if (key == "skip_window") return options.path.skip_window;
  if (key == "path_return_error") return options.path.return_error;
  if (key == "hover_window") return options.hover_window;
  if (key == "recovery_level_tilt_deg") return RecoveryOptions().level_tilt_deg;
  if (key == "recovery_settle_error") return RecoveryOptions().settle_error;
  return kNotReached;
}

std::string_view thresholdUnit(std::string_view key) {
  if (key == "hover_window") return "s";
  const ThresholdSpec* t = findThreshold(key);
  return t ? t->unit : "";
}

std::string formatNumber(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

Check makeCheck(const CriterionSpec& spec, const std::string& window, const std::string& description, double value,
                double limit) {
  Check check;
  check.key = std::string(spec.key);
  check.window = window;
  check.name = window.empty() ? check.key : check.key + "[" + window + "]";
  check.description = description;
  check.unit = std::string(spec.unit);
  check.value = value;
  check.limit = limit;
  check.upper = spec.bound == Bound::kAtMost;
  check.pass = std::isfinite(value) && (check.upper ? value <= limit : value >= limit);
  return check;
}

std::string notJudgedReason(const CriterionSpec& spec, const FlightReport& report) {
  if (spec.needs_heartbeats && report.processes.empty()) return "no process heartbeats (an in-process flight)";
  if (spec.needs_calibration && !report.calibration) {
    return "no calibration of this machine (sdlqr-analyze --calibration FILE from sdlqr-calibrate)";
  }
  return {};
}

// A window of the scenario that has no figures (its event not in the log): NaN, a failed check,
// with the reason as the check's note.
template <class Window, class Of>
std::pair<double, std::string> valueOf(const Window& w, Of of) {
  if (!w.missing.empty()) return {kNotReached, w.missing};
  return {of(w), ""};
}

// A path the guard aborted was not flown: every check of it fails, saying so (its figures, of the
// part flown before the abort, would pass a sweep on a path given up after a fraction of a lap).
std::pair<double, std::string> valueOf(const PathTrackingReport& t, double (*of)(const PathTrackingReport&)) {
  if (t.missing.empty() && std::isfinite(t.aborted_at)) {
    char why[128];
    std::snprintf(why, sizeof why, "aborted into a hold by the guard at %.2f s, %.2f s into the path", t.aborted_at,
                  t.aborted_at - t.start);
    return {kNotReached, why};
  }
  return valueOf<PathTrackingReport>(t, of);  // the windows' rule: figures, or why there are none
}

// Appends the checks of one criterion, one per window of its scope.
void judgeOne(const CriterionSpec& spec, double limit, const std::string& description, FlightReport& report) {
  auto add = [&](const std::string& window, std::pair<double, std::string> value) {
    report.checks.push_back(makeCheck(spec, window, description, value.first, limit));
    report.checks.back().note = std::move(value.second);
  };
  switch (spec.scope) {
    case S::kFlight:
      add("", {spec.of_flight(report), ""});
      break;
    case S::kEvent:
      for (const ExpectedEvent& e : report.events) add(e.label, {spec.of_event(e), e.describe()});
      break;
    case S::kJump:
    case S::kTakeoff:
    case S::kSetpoint:
      for (const SetpointWindow& w : report.setpoints) {
        const bool applies = spec.scope == S::kSetpoint || w.is_jump == (spec.scope == S::kJump);
        if (applies) add(w.label, valueOf(w, spec.of_setpoint));
      }
      break;
    case S::kPull:
      for (const PullWindow& p : report.pulls) add(p.label, valueOf(p, spec.of_pull));
      break;
    case S::kLanding:
      for (const Landing& l : report.landings) add(l.label, valueOf(l, spec.of_landing));
      break;
    case S::kTrajectory:
      for (const PathTrackingReport& t : report.trajectories) add(t.label, valueOf(t, spec.of_trajectory));
      break;
    case S::kTrajectoryPull:
      for (const PathTrackingReport& t : report.trajectories) {
        if (t.pulls.empty()) add(t.label + "][no pull", {kNotReached, t.missing});
        for (const PathPull& p : t.pulls) add(t.label + "][" + p.label, valueOf(p, spec.of_trajectory_pull));
      }
      break;
  }
}

// What a scoped criterion judges, for the check that fails when the scenario holds none of it.
const char* windowsOf(Scope scope) {
  switch (scope) {
    case S::kJump: return "jump (goto)";
    case S::kTakeoff: return "takeoff";
    case S::kSetpoint: return "takeoff or jump";
    case S::kPull: return "pull while holding a setpoint";
    case S::kLanding: return "land";
    case S::kTrajectory:
    case S::kTrajectoryPull: return "trajectory";
    default: return "event";
  }
}

}  // namespace

const std::vector<CriterionSpec>& criteria() {
  static const std::vector<CriterionSpec> table = makeCriteria();
  return table;
}

const std::vector<ThresholdSpec>& thresholds() {
  static const std::vector<ThresholdSpec> table = {
      {"jump_settle_error", "m", "error a jump must settle below (jump_settle_time)"},
      {"pull_return_error", "m", "distance to the setpoint counted as back after a pull (pull_return_time)"},
      {"skip_radius", "m", "a trajectory sample the vehicle came this close to was visited"},
      {"skip_window", "m", "path either side of a sample within which a visit counts"},
      {"path_return_error", "m", "distance to the path counted as back on it after a pull (path_return_time)"},
      {"recovery_level_tilt_deg", "deg", "tilt counted as level after a bad start (recovery_level_time)"},
      {"recovery_settle_error", "m", "distance to the reference counted as settled (recovery_settle_time)"},
  };
  return table;
}

const CriterionSpec* findCriterion(std::string_view key) {
  for (const CriterionSpec& c : criteria()) {
    if (c.key == key) return &c;
  }
  return nullptr;
}

const ThresholdSpec* findThreshold(std::string_view key) {
  for (const ThresholdSpec& t : thresholds()) {
    if (t.key == key) return &t;
  }
  return nullptr;
}

std::string formatQuantity(double value, std::string_view unit) {
  if (!std::isfinite(value)) return "n/a";
  if (unit == "m" && std::abs(value) < 1.0) return formatNumber(value * 100.0) + " cm";
  if (unit == "-" || unit == "count" || unit.empty()) return formatNumber(value);
  return formatNumber(value) + " " + std::string(unit);
}

std::string describe(const CriterionSpec& spec, const mission::Scenario& scenario, const AnalysisOptions& options) {
  std::string text(spec.description);
  for (size_t open = text.find('{'); open != std::string::npos; open = text.find('{', open)) {
    const size_t close = text.find('}', open);
    if (close == std::string::npos) break;
    const std::string key = text.substr(open + 1, close - open - 1);
    const double value = scenario.criterion(key, thresholdDefault(key, options));
    const std::string quantity = formatQuantity(value, thresholdUnit(key));
    text.replace(open, close - open + 1, quantity);
    open += quantity.size();
  }
  return text;
}

void checkCriteriaKeys(const mission::Scenario& scenario) {
  for (const auto& [key, value] : scenario.criteria) {
    if (!findCriterion(key) && !findThreshold(key)) {
      throw std::invalid_argument("criteria." + key + ": unknown criterion (see tools/examine/analysis/src/criteria.cpp)");
    }
  }
}

void judgeCriteria(FlightReport& report, const mission::Scenario& scenario, const AnalysisOptions& options) {
  for (const CriterionSpec& spec : criteria()) {
    const auto it = scenario.criteria.find(std::string(spec.key));
    if (!spec.always && it == scenario.criteria.end()) continue;
    const std::string reason = notJudgedReason(spec, report);
    if (!reason.empty()) {
      report.not_judged.push_back({std::string(spec.key), reason});
      continue;
    }
    const size_t before = report.checks.size();
    const double limit = it == scenario.criteria.end() ? spec.default_limit : it->second;
    judgeOne(spec, limit, describe(spec, scenario, options), report);
    // A criterion of windows the scenario never plays judges nothing: that fails, it never passes.
    if (report.checks.size() == before && spec.scope != S::kFlight && spec.scope != S::kEvent) {
      report.checks.push_back(makeCheck(spec, "", describe(spec, scenario, options), kNotReached, limit));
      report.checks.back().note = std::string("the scenario has no ") + windowsOf(spec.scope) + " for it to judge";
    }
  }
}

}  // namespace sdlqr::analysis
