#include "sdlqr/analysis/flight_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::analysis {

namespace {

double seconds(int64_t utime) { return static_cast<double>(utime) * 1e-6; }

struct Event {
  double t = 0.0;
  enum Kind { kTakeoff, kGoto, kLand, kPull, kTrajectory } kind = kGoto;
  Vec3 position = Vec3::Zero();
  const Disturbance* disturbance = nullptr;
  std::string label;
};

std::vector<Event> flightEvents(const logger::FlightLog& log, const mission::Scenario& scenario) {
  std::vector<Event> events;
  std::set<int64_t> command_seqs;
  for (const Command& c : log.command.messages) {
    // sdlqr-mission re-sends its current command once a second (same seq) for a restarted
    // controller: one event per command.
    if (!command_seqs.insert(c.seq).second) continue;
    Event e;
    e.t = seconds(c.utime);
    e.position = c.position;
    if (c.command == CommandType::kTakeoff) e.kind = Event::kTakeoff;
    else if (c.command == CommandType::kGoto) e.kind = Event::kGoto;
    else if (c.command == CommandType::kLand) e.kind = Event::kLand;
    else continue;
    events.push_back(e);
  }
  for (const Disturbance& d : log.disturbance.messages) {
    Event e;
    e.t = seconds(d.start_utime > 0 ? d.start_utime : d.utime);
    e.kind = Event::kPull;
    e.disturbance = &d;
    events.push_back(e);
  }
  // A trajectory ends the setpoint window before it (path_tracking.hpp judges the flight on it).
  for (const Trajectory& t : log.trajectory.messages) {
    Event e;
    e.t = seconds(t.start_utime > 0 ? t.start_utime : t.utime);
    e.kind = Event::kTrajectory;
    e.label = "trajectory";
    events.push_back(e);
  }
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
  // Labels come from the scenario: its events of the same kind, in the same order.
  std::vector<const mission::ScenarioEvent*> commands, pulls;
  for (const mission::ScenarioEvent& s : scenario.events) {
    if (s.kind == mission::ScenarioEvent::Kind::kCommand &&
        (s.command.command == CommandType::kGoto || s.command.command == CommandType::kTakeoff ||
         s.command.command == CommandType::kLand)) {
      commands.push_back(&s);
    } else if (s.kind == mission::ScenarioEvent::Kind::kDisturbance) {
      pulls.push_back(&s);
    }
  }
  size_t next_command = 0, next_pull = 0;
  for (Event& e : events) {
    if (e.kind == Event::kTrajectory) continue;
    const mission::ScenarioEvent* source = nullptr;
    if (e.kind == Event::kPull) {
      if (next_pull < pulls.size()) source = pulls[next_pull++];
    } else if (next_command < commands.size()) {
      source = commands[next_command++];
    }
    if (source && !source->label.empty()) e.label = source->label;
    if (e.label.empty()) {
      static const char* names[] = {"takeoff", "goto", "land", "pull"};
      e.label = names[e.kind];
    }
  }
  return events;
}

// Held reference position shortly before `t` (the controller publishes it every tick).
Vec3 referencePositionBefore(const logger::FlightLog& log, double t) {
  const auto i = log.reference.indexAtOrBefore(static_cast<int64_t>(t * 1e6) - 20000);
  if (i < 0) return Vec3::Constant(kNotReached);
  return position(log.reference[static_cast<size_t>(i)].x);
}

template <class Visit>
void forTruthIn(const logger::FlightLog& log, double start, double end, Visit visit) {
  const auto& truth = log.sim_truth.messages;
  auto it = std::lower_bound(truth.begin(), truth.end(), start,
                             [](const SimTruth& s, double t) { return seconds(s.utime) < t; });
  for (; it != truth.end() && seconds(it->utime) <= end; ++it) visit(*it);
}

// Time after `from` at which err stays below `threshold` until `end`; NaN if it ends above.
template <class ErrorOf>
double settleTime(const logger::FlightLog& log, double from, double end, double threshold, ErrorOf error_of) {
  double last_above = -1.0;
  double last_t = from;
  bool any = false;
  forTruthIn(log, from, end, [&](const SimTruth& s) {
    any = true;
    last_t = seconds(s.utime);
    if (error_of(s) >= threshold) last_above = last_t;
  });
  if (!any || last_above >= last_t) return kNotReached;
  return last_above < 0.0 ? 0.0 : last_above - from;
}

double attitudeErrorDeg(const Quat& a, const Quat& b) {
  const double w = std::min(1.0, std::abs(a.normalized().dot(b.normalized())));
  return 2.0 * std::acos(w) * 180.0 / M_PI;
}

template <class T>
bool finiteMessage(const T& m);
template <>
bool finiteMessage(const StateEstimate& m) {
  return m.position.allFinite() && m.orientation.allFinite() && m.velocity.allFinite() && m.body_rate.allFinite();
}
template <>
bool finiteMessage(const RateCommand& m) {
  return m.body_rate.allFinite() && std::isfinite(m.thrust);
}
template <>
bool finiteMessage(const GainSet& m) {
  return m.K.allFinite() && m.x_lin.allFinite() && m.u_lin.allFinite();
}

template <class T>
double rateIn(const logger::Series<T>& series, double start, double end) {
  if (!(end > start)) return 0.0;
  int64_t count = 0;
  for (const T& m : series.messages) {
    const double t = seconds(m.utime);
    if (t >= start && t < end) ++count;
  }
  return static_cast<double>(count) / (end - start);
}

void addCheck(FlightReport& report, const std::string& name, double value, double limit, bool upper) {
  Check check;
  check.name = name;
  check.value = value;
  check.limit = limit;
  check.upper = upper;
  check.pass = std::isfinite(value) && (upper ? value <= limit : value >= limit);
  report.checks.push_back(check);
}

const std::set<std::string>& knownCriteria() {
  static const std::set<std::string> keys = {
      "jump_settle_error", "jump_settle_time", "jump_max_overshoot", "hover_error", "pull_return_error",
      "pull_return_time", "estimator_position_rms", "estimator_attitude_rms_deg", "gains_rate_min",
      "gains_rate_max", "rate_cmd_rate_min", "rate_cmd_rate_max", "state_est_rate_min", "state_est_rate_max",
      "max_tilt_deg", "touchdown_speed_max", "rate_cmd_jitter_p99_ms", "stack_cpu_percent_max",
      // trajectories (path_tracking.hpp)
      "path_error_rms", "path_error_max", "skipped_samples_max", "skipped_samples_min", "skip_radius", "skip_window",
      "path_return_error", "path_return_time", "trajectory_laps_min", "trajectory_completed",
      "thrust_limit_violations_max"};
  return keys;
}

}  // namespace

bool FlightReport::passed() const {
  return std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.pass; });
}

FlightReport analyzeFlight(const logger::FlightLog& log, const mission::Scenario& scenario, AnalysisOptions options) {
  for (const auto& [key, value] : scenario.criteria) {
    if (!knownCriteria().count(key)) throw std::invalid_argument("criteria." + key + ": unknown criterion");
  }
  const auto criterion = [&](const char* key) { return scenario.criterion(key, kNotReached); };
  const auto has = [&](const char* key) { return scenario.criteria.count(key) > 0; };

  FlightReport report;
  report.scenario = scenario.name;

  // Airborne span, tilt, touchdown speed, crash, from the truth.
  bool previous_on_ground = true;
  double previous_vz = 0.0;
  for (const SimTruth& s : log.sim_truth.messages) {
    const double t = seconds(s.utime);
    if (!s.on_ground) {
      if (!std::isfinite(report.flight_start)) report.flight_start = t;
      report.flight_end = t;
      report.max_tilt_deg = std::max(report.max_tilt_deg, quat::tilt(s.orientation) * 180.0 / M_PI);
    } else if (!previous_on_ground) {
      report.touchdown_speed = std::max(report.touchdown_speed, std::abs(previous_vz));
    }
    report.crashed = report.crashed || s.crashed;
    previous_on_ground = s.on_ground;
    previous_vz = s.velocity[2];
  }
  const double log_end = log.sim_truth.empty() ? 0.0 : seconds(log.sim_truth.back().utime);

  // Setpoint windows and pulls.
  const std::vector<Event> events = flightEvents(log, scenario);
  const double settle_error = has("jump_settle_error") ? criterion("jump_settle_error") : options.settle_error;
  const double return_error = has("pull_return_error") ? criterion("pull_return_error") : options.return_error;
  Vec3 previous_setpoint = Vec3::Constant(kNotReached);
  bool on_trajectory = false;  // pulls while tracking a trajectory are judged against the path
  for (size_t i = 0; i < events.size(); ++i) {
    const Event& e = events[i];
    if (e.kind != Event::kPull) on_trajectory = e.kind == Event::kTrajectory;
    if (on_trajectory) previous_setpoint = Vec3::Constant(kNotReached);
    const double end = i + 1 < events.size() ? events[i + 1].t : log_end;
    if (e.kind == Event::kTakeoff || e.kind == Event::kGoto) {
      SetpointWindow w;
      w.label = e.label;
      w.is_jump = e.kind == Event::kGoto;
      w.start = e.t;
      w.end = end;
      w.to = e.kind == Event::kGoto ? e.position : referencePositionBefore(log, end);
      w.from = previous_setpoint.allFinite() ? previous_setpoint : w.to;
      w.size = (w.to - w.from).norm();
      const Vec3 to = w.to;
      const auto error_of = [&to](const SimTruth& s) { return (s.position - to).norm(); };
      w.settle_time = settleTime(log, w.start, w.end, settle_error, error_of);
      const Vec3 direction = w.size > 1e-9 ? Vec3((w.to - w.from) / w.size) : Vec3::Zero();
      double beyond = 0.0, steady_sum = 0.0, after_settle = 0.0;
      int64_t steady_count = 0;
      const double settled_at = w.start + (std::isfinite(w.settle_time) ? w.settle_time : 1e9);
      forTruthIn(log, w.start, w.end, [&](const SimTruth& s) {
        const double t = seconds(s.utime);
        beyond = std::max(beyond, (s.position - to).dot(direction));
        if (t >= w.end - options.hover_window) {
          steady_sum += error_of(s);
          ++steady_count;
        }
        if (t >= settled_at) after_settle = std::max(after_settle, error_of(s));
      });
      w.overshoot = w.size > 1e-9 ? beyond / w.size : 0.0;
      if (steady_count > 0) w.steady_error = steady_sum / static_cast<double>(steady_count);
      if (std::isfinite(w.settle_time)) w.max_error_after_settle = after_settle;
      previous_setpoint = w.to;
      report.setpoints.push_back(w);
    } else if (e.kind == Event::kPull && !on_trajectory) {
      PullWindow p;
      p.label = e.label;
      p.start = e.t;
      p.release = e.t + e.disturbance->duration;
      p.end = end;
      p.force = e.disturbance->force;
      p.setpoint = referencePositionBefore(log, e.t + 0.02);
      const Vec3 sp = p.setpoint;
      const auto error_of = [&sp](const SimTruth& s) { return (s.position - sp).norm(); };
      forTruthIn(log, p.start, p.end, [&](const SimTruth& s) { p.max_deviation = std::max(p.max_deviation, error_of(s)); });
      p.return_time = settleTime(log, p.release, p.end, return_error, error_of);
      report.pulls.push_back(p);
    }
  }

  // Estimator accuracy against the truth at the same instant (interpolated).
  double sum_p = 0, sum_a = 0, sum_p_all = 0, sum_a_all = 0, max_p = 0;
  int64_t n = 0, n_all = 0;
  for (const StateEstimate& est : log.state_estimate.messages) {
    if (est.status == EstimatorStatus::kInitializing) continue;
    const auto i = log.sim_truth.indexAtOrBefore(est.utime);
    if (i < 0 || static_cast<size_t>(i) + 1 >= log.sim_truth.size()) continue;
    const SimTruth& a = log.sim_truth[static_cast<size_t>(i)];
    const SimTruth& b = log.sim_truth[static_cast<size_t>(i) + 1];
    if (a.on_ground || b.on_ground || a.position[2] < 0.05) continue;
    const double span = static_cast<double>(b.utime - a.utime);
    const double f = span > 0 ? static_cast<double>(est.utime - a.utime) / span : 0.0;
    const Vec3 p_true = a.position + f * (b.position - a.position);
    const Quat q_true = f < 0.5 ? a.orientation : b.orientation;
    const double ep = (est.position - p_true).norm();
    const double ea = attitudeErrorDeg(est.orientation, q_true);
    sum_p_all += ep * ep;
    sum_a_all += ea * ea;
    max_p = std::max(max_p, ep);
    ++n_all;
    if (a.velocity.norm() < 0.3) {
      sum_p += ep * ep;
      sum_a += ea * ea;
      ++n;
    }
  }
  report.estimator.samples = n;
  if (n > 0) {
    report.estimator.position_rms = std::sqrt(sum_p / static_cast<double>(n));
    report.estimator.attitude_rms_deg = std::sqrt(sum_a / static_cast<double>(n));
  }
  if (n_all > 0) {
    report.estimator.position_rms_all = std::sqrt(sum_p_all / static_cast<double>(n_all));
    report.estimator.attitude_rms_deg_all = std::sqrt(sum_a_all / static_cast<double>(n_all));
    report.estimator.position_max_all = max_p;
  }

  // Rates over the airborne span (one second trimmed at each end for start-up and landing).
  if (std::isfinite(report.flight_start)) {
    const double a = report.flight_start + 1.0, b = report.flight_end - 1.0;
    report.imu_rate_hz = rateIn(log.imu, a, b);
    report.state_est_rate_hz = rateIn(log.state_estimate, a, b);
    report.rate_cmd_rate_hz = rateIn(log.rate_command, a, b);
    report.gains_rate_hz = rateIn(log.gains, a, b);
  }

  // Timing.
  std::vector<double> solve, iterations, period, jitter, latency;
  for (const GainSet& g : log.gains.messages) {
    solve.push_back(g.solve_us);
    iterations.push_back(g.iterations);
  }
  for (size_t i = 1; i < log.rate_command.size(); ++i) {
    const double dt = seconds(log.rate_command[i].utime - log.rate_command[i - 1].utime);
    if (dt > 5.0 * options.rate_cmd_period_s) continue;  // a pause (idle on the ground), not jitter
    period.push_back(dt * 1e3);
    jitter.push_back(std::abs(dt - options.rate_cmd_period_s) * 1e3);
  }
  {
    std::map<int64_t, int64_t> state_receive;  // STATE_EST seq -> receive time at the recorder
    for (size_t i = 0; i < log.state_estimate.size(); ++i) {
      state_receive[log.state_estimate[i].seq] = log.state_estimate.receive_utime[i];
    }
    for (size_t i = 0; i < log.rate_command.size(); ++i) {
      const auto it = state_receive.find(log.rate_command[i].state_seq);
      if (it != state_receive.end()) {
        latency.push_back(static_cast<double>(log.rate_command.receive_utime[i] - it->second));
      }
    }
  }
  report.solve_us = logger::describe(solve);
  report.iterations = logger::describe(iterations);
  report.rate_cmd_period_ms = logger::describe(period);
  report.rate_cmd_jitter_ms = logger::describe(jitter);
  report.state_to_command_us = logger::describe(latency);

  // Non-finite values anywhere in the loop.
  for (const auto& m : log.state_estimate.messages) report.nonfinite += finiteMessage(m) ? 0 : 1;
  for (const auto& m : log.rate_command.messages) report.nonfinite += finiteMessage(m) ? 0 : 1;
  for (const auto& m : log.gains.messages) report.nonfinite += finiteMessage(m) ? 0 : 1;

  // Load per process from the heartbeats sent while airborne.
  std::map<std::string, ProcessLoad> loads;
  std::map<std::string, int64_t> beats;
  for (const logger::HeartbeatRecord& hb : log.heartbeat.messages) {
    ProcessLoad& load = loads[hb.process];
    load.process = hb.process;
    load.rejected = std::max(load.rejected, hb.rejected);
    load.dropped = std::max(load.dropped, hb.dropped);
    load.deadline_misses = std::max(load.deadline_misses, hb.deadline_misses);
    load.errors = std::max(load.errors, hb.errors);
    const double t = seconds(hb.utime);
    if (!std::isfinite(report.flight_start) || t < report.flight_start + 1.0 || t > report.flight_end) continue;
    load.cpu_percent_mean += hb.cpu_percent;
    load.cpu_percent_max = std::max(load.cpu_percent_max, hb.cpu_percent);
    ++beats[hb.process];
  }
  for (auto& [name, load] : loads) {
    if (beats[name] > 0) load.cpu_percent_mean /= static_cast<double>(beats[name]);
    if (name != "sdlqr-logger" && name != "sdlqr-mission") report.stack_cpu_percent += load.cpu_percent_mean;
    report.processes.push_back(load);
  }

  // Trajectory tracking, labelled by the scenario's trajectory events in order.
  PathTrackingOptions path_options = options.path;
  if (has("skip_radius")) path_options.skip_radius = criterion("skip_radius");
  if (has("skip_window")) path_options.skip_window = criterion("skip_window");
  if (has("path_return_error")) path_options.return_error = criterion("path_return_error");
  if (has("thrust_limit_violations_max") &&
      !(std::isfinite(path_options.thrust_min) && std::isfinite(path_options.thrust_max))) {
    throw std::invalid_argument("criteria.thrust_limit_violations_max: needs the vehicle's thrust limits");
  }
  report.trajectories = analyzePathTracking(log, path_options);
  {
    std::vector<std::string> labels;
    for (const mission::ScenarioEvent& s : scenario.events) {
      if (s.kind == mission::ScenarioEvent::Kind::kTrajectory) labels.push_back(s.label);
    }
    for (size_t i = 0; i < report.trajectories.size(); ++i) {
      PathTrackingReport& t = report.trajectories[i];
      t.label = i < labels.size() && !labels[i].empty() ? labels[i] : "trajectory " + std::to_string(i + 1);
    }
  }

  // Checks: always no NaN and no crash; then every criterion the scenario names.
  addCheck(report, "nonfinite_messages", static_cast<double>(report.nonfinite), 0.0, true);
  addCheck(report, "crashed", report.crashed ? 1.0 : 0.0, 0.0, true);
  for (const SetpointWindow& w : report.setpoints) {
    if (w.is_jump && has("jump_settle_time")) {
      addCheck(report, "jump_settle_time[" + w.label + "]", w.settle_time, criterion("jump_settle_time"), true);
    }
    if (w.is_jump && has("jump_max_overshoot")) {
      addCheck(report, "jump_max_overshoot[" + w.label + "]", w.overshoot, criterion("jump_max_overshoot"), true);
    }
    if (has("hover_error")) addCheck(report, "hover_error[" + w.label + "]", w.steady_error, criterion("hover_error"), true);
  }
  for (const PullWindow& p : report.pulls) {
    if (has("pull_return_time")) {
      addCheck(report, "pull_return_time[" + p.label + "]", p.return_time, criterion("pull_return_time"), true);
    }
  }
  if (has("estimator_position_rms")) {
    addCheck(report, "estimator_position_rms", report.estimator.position_rms, criterion("estimator_position_rms"), true);
  }
  if (has("estimator_attitude_rms_deg")) {
    addCheck(report, "estimator_attitude_rms_deg", report.estimator.attitude_rms_deg,
             criterion("estimator_attitude_rms_deg"), true);
  }
  const std::pair<const char*, double> rates[] = {{"gains_rate", report.gains_rate_hz},
                                                  {"rate_cmd_rate", report.rate_cmd_rate_hz},
                                                  {"state_est_rate", report.state_est_rate_hz}};
  for (const auto& [name, value] : rates) {
    const std::string min_key = std::string(name) + "_min", max_key = std::string(name) + "_max";
    if (has(min_key.c_str())) addCheck(report, min_key, value, criterion(min_key.c_str()), false);
    if (has(max_key.c_str())) addCheck(report, max_key, value, criterion(max_key.c_str()), true);
  }
  if (has("max_tilt_deg")) addCheck(report, "max_tilt_deg", report.max_tilt_deg, criterion("max_tilt_deg"), true);
  if (has("touchdown_speed_max")) {
    addCheck(report, "touchdown_speed_max", report.touchdown_speed, criterion("touchdown_speed_max"), true);
  }
  if (has("rate_cmd_jitter_p99_ms")) {
    addCheck(report, "rate_cmd_jitter_p99_ms", report.rate_cmd_jitter_ms.p99, criterion("rate_cmd_jitter_p99_ms"), true);
  }
  const bool judges_trajectories = has("path_error_rms") || has("path_error_max") || has("skipped_samples_max") ||
                                   has("skipped_samples_min") || has("path_return_time") ||
                                   has("trajectory_laps_min") || has("trajectory_completed") ||
                                   has("thrust_limit_violations_max");
  if (judges_trajectories && report.trajectories.empty()) addCheck(report, "trajectories_tracked", 0.0, 1.0, false);
  for (const PathTrackingReport& t : report.trajectories) {
    const std::string tag = "[" + t.label + "]";
    if (has("path_error_rms")) addCheck(report, "path_error_rms" + tag, t.path_error_rms, criterion("path_error_rms"), true);
    if (has("path_error_max")) addCheck(report, "path_error_max" + tag, t.path_error_max, criterion("path_error_max"), true);
    const double skipped = static_cast<double>(t.skipped.size());
    if (has("skipped_samples_max")) addCheck(report, "skipped_samples_max" + tag, skipped, criterion("skipped_samples_max"), true);
    if (has("skipped_samples_min")) addCheck(report, "skipped_samples_min" + tag, skipped, criterion("skipped_samples_min"), false);
    if (has("trajectory_laps_min")) addCheck(report, "trajectory_laps_min" + tag, t.laps, criterion("trajectory_laps_min"), false);
    if (has("trajectory_completed")) {
      addCheck(report, "trajectory_completed" + tag, t.completed ? 1.0 : 0.0, criterion("trajectory_completed"), false);
    }
    if (has("thrust_limit_violations_max")) {
      addCheck(report, "thrust_limit_violations_max" + tag, static_cast<double>(t.thrust_violations),
               criterion("thrust_limit_violations_max"), true);
    }
    if (has("path_return_time")) {
      if (t.pulls.empty()) addCheck(report, "path_return_time" + tag + "[no pull]", kNotReached, 0.0, true);
      for (size_t i = 0; i < t.pulls.size(); ++i) {
        addCheck(report, "path_return_time" + tag + "[pull " + std::to_string(i + 1) + "]", t.pulls[i].return_time,
                 criterion("path_return_time"), true);
      }
    }
  }
  // CPU comes from the HEARTBEATs of a bus flight; an in-process flight has none to judge.
  if (has("stack_cpu_percent_max") && !report.processes.empty()) {
    addCheck(report, "stack_cpu_percent_max", report.stack_cpu_percent, criterion("stack_cpu_percent_max"), true);
  }
  return report;
}

}  // namespace sdlqr::analysis
