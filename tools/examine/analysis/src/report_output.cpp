#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/tables/json_document.hpp"

namespace sdlqr::analysis {

namespace {

using tables::JsonDocument;
using tables::toJson;

JsonDocument vec3(const Vec3& v) { return JsonDocument::array({v[0], v[1], v[2]}); }

std::string format(const char* fmt, double value) {
  if (!std::isfinite(value)) return "never";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, fmt, value);
  return buffer;
}

std::string formatVec3(const Vec3& v, const char* unit) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.2f, %.2f, %.2f) %s", v[0], v[1], v[2], unit);
  return buffer;
}

const char* disturbanceKind(const Disturbance& d) {
  if (d.mode == DisturbanceMode::kHold) return "hold";
  if (d.torque.isZero()) return "force";
  return d.force.isZero() ? "torque" : "force+torque";
}

JsonDocument checkJson(const Check& c) {
  JsonDocument out = {{"name", c.name}, {"key", c.key}, {"window", c.window}, {"description", c.description},
                      {"unit", c.unit}, {"value", c.value}, {"limit", c.limit}, {"rule", c.upper ? "<=" : ">="},
                      {"pass", c.pass}};
  if (!c.note.empty()) out["note"] = c.note;
  return out;
}

void addChecks(JsonDocument& json, const FlightReport& r) {
  JsonDocument& checks = json["checks"] = JsonDocument::array();
  for (const Check& c : r.checks) checks.push_back(checkJson(c));
  JsonDocument& not_judged = json["not_judged"] = JsonDocument::array();
  for (const NotJudged& n : r.not_judged) not_judged.push_back({{"key", n.key}, {"reason", n.reason}});
}

// The scenario's events as the log had them, and the touchdown after each LAND.
void addEvents(JsonDocument& json, const FlightReport& r) {
  JsonDocument& events = json["events"] = JsonDocument::array();
  for (const ExpectedEvent& e : r.events) {
    events.push_back({{"label", e.label}, {"channel", e.channel}, {"at_s", e.at}, {"in_log", e.found()},
                      {"seen_s", e.seen}});
  }
  JsonDocument& landings = json["landings"] = JsonDocument::array();
  for (const Landing& l : r.landings) {
    landings.push_back({{"label", l.label}, {"start_s", l.start}, {"touchdown_s", l.touchdown},
                        {"touchdown_speed_mps", l.touchdown_speed}});
  }
}

void addCalibration(JsonDocument& json, const FlightReport& r) {
  if (!r.calibration) return;
  const calibrate::Calibration& c = *r.calibration;
  json["calibration"] = {{"echo_rate_hz", c.echo_rate_hz}, {"rtt_median_us", c.rtt_median_us},
                         {"rtt_p99_us", c.rtt_p99_us}, {"cpu_percent", c.cpu_percent}, {"host", c.host},
                         {"date", c.date}};
  json["stack_cpu_relative"] = r.stack_cpu_relative;
  json["state_to_command_relative"] = r.state_to_command_relative;
}

JsonDocument setpointJson(const SetpointWindow& w) {
  return {{"label", w.label}, {"jump", w.is_jump}, {"start_s", w.start}, {"end_s", w.end}, {"from_m", vec3(w.from)},
          {"to_m", vec3(w.to)}, {"size_m", w.size}, {"settle_time_s", w.settle_time}, {"overshoot", w.overshoot},
          {"steady_error_m", w.steady_error}, {"max_error_after_settle_m", w.max_error_after_settle}};
}

JsonDocument pullJson(const PullWindow& p) {
  JsonDocument out = {{"label", p.label}, {"start_s", p.start}, {"release_s", p.release},
                      {"kind", disturbanceKind(p.disturbance)}, {"force_n", vec3(p.disturbance.force)},
                      {"torque_nm", vec3(p.disturbance.torque)}};
  if (p.disturbance.mode == DisturbanceMode::kHold) {
    out["hold_position_m"] = vec3(p.disturbance.hold_position);
    out["hold_stiffness_n_per_m"] = p.disturbance.hold_stiffness;
  }
  out["setpoint_m"] = vec3(p.setpoint);
  out["max_deviation_m"] = p.max_deviation;
  out["return_time_s"] = p.return_time;
  out["return_overshoot"] = p.return_overshoot;
  return out;
}

JsonDocument trajectoryJson(const PathTrackingReport& t) {
  JsonDocument out = {
      {"label", t.label}, {"trajectory_seq", t.trajectory_seq},
      {"tracking", t.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial"}, {"closed", t.closed},
      {"samples", t.samples}, {"path_length_m", t.path_length}, {"duration_s", t.duration}, {"start_s", t.start},
      {"entry_time_s", t.entry_time}, {"end_s", t.end}, {"completed", t.completed}, {"completion_time_s", t.completion_time},
      {"remaining_m", t.remaining}, {"laps", t.laps}, {"aborted_at_s", t.aborted_at}, {"truth_samples", t.truth_samples},
      {"path_error_rms_m", t.path_error_rms}, {"path_error_max_m", t.path_error_max},
      {"path_error_rms_axis_m", vec3(t.path_error_rms_axis)}, {"path_error_max_axis_m", vec3(t.path_error_max_axis)},
      {"time_error_rms_m", t.time_error_rms}, {"time_error_max_m", t.time_error_max},
      {"samples_passed", t.samples_passed}, {"samples_skipped", static_cast<int64_t>(t.skipped.size())},
      {"worst_visit_m", t.worst_visit}};
  JsonDocument& skipped = out["skipped"] = JsonDocument::array();
  for (const SkippedSample& k : t.skipped) {
    skipped.push_back({{"lap", k.lap}, {"index", k.index}, {"arc_m", k.arc}, {"closest_m", k.closest}});
  }
  out["commands"] = t.commands;
  out["saturation_percent"] = t.saturation_percent;
  out["rate_saturation_percent"] = t.rate_saturation_percent;
  out["thrust_saturation_percent"] = t.thrust_saturation_percent;
  out["thrust_min"] = t.thrust_min;
  out["thrust_max"] = t.thrust_max;
  out["thrust_violations"] = t.thrust_violations;
  JsonDocument& pulls = out["pulls"] = JsonDocument::array();
  for (const PathPull& p : t.pulls) {
    pulls.push_back({{"start_s", p.start}, {"release_s", p.release}, {"max_distance_m", p.max_distance},
                     {"distance_at_release_m", p.distance_at_release}, {"return_time_s", p.return_time}});
  }
  return out;
}

// Figures of the machine: rates, the solver, timing, saturation, each process's load and losses.
void addMachineFigures(JsonDocument& json, const FlightReport& r) {
  json["rates_hz"] = {{"IMU", r.imu_rate_hz}, {"STATE_EST", r.state_est_rate_hz}, {"RATE_CMD", r.rate_cmd_rate_hz},
                      {"GAINS", r.gains_rate_hz}};
  json["gains_solve_us"] = toJson(r.solve_us);
  json["gains_iterations"] = toJson(r.iterations);
  json["rate_cmd_period_ms"] = toJson(r.rate_cmd_period_ms);
  json["rate_cmd_jitter_ms"] = toJson(r.rate_cmd_jitter_ms);
  json["state_est_to_rate_cmd_us"] = toJson(r.state_to_command_us);
  json["rate_cmd_wall_jitter_us"] = toJson(r.rate_cmd_wall_jitter_us);
  json["saturation"] = {{"rate_commands", r.saturation.commands},
                        {"thrust_demand_outside", r.saturation.thrust_demand_outside},
                        {"thrust_demand_min", r.saturation.thrust_demand_min},
                        {"thrust_demand_max", r.saturation.thrust_demand_max},
                        {"motor_commands", r.saturation.motor_commands},
                        {"rotor_at_limit", r.saturation.rotor_at_limit}};
  JsonDocument& processes = json["processes"] = JsonDocument::array();
  for (const ProcessLoad& p : r.processes) {
    processes.push_back({{"process", p.process}, {"cpu_percent_mean", p.cpu_percent_mean},
                         {"cpu_percent_max", p.cpu_percent_max}, {"rejected", p.rejected}, {"dropped", p.dropped},
                         {"deadline_misses", p.deadline_misses}, {"errors", p.errors}});
  }
  JsonDocument& loss = json["message_loss"] = JsonDocument::array();
  for (const ChannelLoss& l : r.message_loss) {
    loss.push_back({{"process", l.process}, {"channel", l.channel}, {"lost", l.lost},
                    {"queue_dropped", l.queue_dropped}});
  }
}

}  // namespace

void writeJson(const FlightReport& r, std::ostream& out) {
  JsonDocument json = {{"scenario", r.scenario}, {"passed", r.passed()}, {"flight_start_s", r.flight_start},
                       {"flight_end_s", r.flight_end}};
  addEvents(json, r);
  JsonDocument& setpoints = json["setpoints"] = JsonDocument::array();
  for (const SetpointWindow& w : r.setpoints) setpoints.push_back(setpointJson(w));
  JsonDocument& pulls = json["pulls"] = JsonDocument::array();
  for (const PullWindow& p : r.pulls) pulls.push_back(pullJson(p));
  JsonDocument& trajectories = json["trajectories"] = JsonDocument::array();
  for (const PathTrackingReport& t : r.trajectories) trajectories.push_back(trajectoryJson(t));
  json["estimator"] = {{"hover_samples", r.estimator.samples}, {"position_rms_m", r.estimator.position_rms},
                       {"attitude_rms_deg", r.estimator.attitude_rms_deg},
                       {"position_rms_all_m", r.estimator.position_rms_all},
                       {"attitude_rms_all_deg", r.estimator.attitude_rms_deg_all},
                       {"position_max_all_m", r.estimator.position_max_all}};
  addMachineFigures(json, r);
  json["stack_cpu_percent"] = r.stack_cpu_percent;
  addCalibration(json, r);
  json["nonfinite_messages"] = r.nonfinite;
  json["max_tilt_deg"] = r.max_tilt_deg;
  json["touchdown_speed_mps"] = r.touchdown_speed;
  json["crashed"] = r.crashed;
  addChecks(json, r);
  tables::writeJsonDocument(out, json);
  out << "\n";
}

namespace {

// Lost messages per subscriber and channel (only the non-zero ones) and deadline misses: the
// figures a lossy or starved flight is read by.
void writeLossSummary(const FlightReport& r, std::ostream& out) {
  char item[160];
  std::string lost;
  for (const ChannelLoss& l : r.message_loss) {
    if (l.lost == 0 && l.queue_dropped == 0) continue;
    std::snprintf(item, sizeof item, " %s %s %lld", l.process.c_str(), l.channel.c_str(), static_cast<long long>(l.lost));
    lost += item;
    if (l.queue_dropped > 0) {
      std::snprintf(item, sizeof item, " (queue %lld)", static_cast<long long>(l.queue_dropped));
      lost += item;
    }
    lost += ",";
  }
  if (!lost.empty()) lost.pop_back();
  out << "  messages lost (subscriber channel count):" << (lost.empty() ? " none" : lost) << "\n";
  std::string misses;
  for (const ProcessLoad& p : r.processes) {
    if (p.deadline_misses == 0) continue;
    std::snprintf(item, sizeof item, " %s %lld,", p.process.c_str(), static_cast<long long>(p.deadline_misses));
    misses += item;
  }
  if (!misses.empty()) misses.pop_back();
  if (!r.processes.empty()) out << "  deadline misses:" << (misses.empty() ? " none" : misses) << "\n";
}

// "force (0.00, 2.00, 0.00) N for 0.50 s", "torque (...) N m for 0.15 s", "spring hold at ...".
std::string describeDisturbance(const Disturbance& d) {
  std::string text;
  if (d.mode == DisturbanceMode::kHold) {
    char buffer[128];
    std::snprintf(buffer, sizeof buffer, "spring %.0f N/m holding at ", d.hold_stiffness);
    text = buffer + formatVec3(d.hold_position, "m");
  } else {
    if (!d.force.isZero() || d.torque.isZero()) text = "force " + formatVec3(d.force, "N");
    if (!d.torque.isZero()) text += (text.empty() ? "torque " : " + torque ") + formatVec3(d.torque, "N m");
  }
  return text + format(" for %.2f s", d.duration);
}

// Each window's row, or in its place why it has none (its `missing`).
template <typename Window, typename WriteRow>
void writeWindows(const std::vector<Window>& windows, const char* indent, std::ostream& out, WriteRow write_row) {
  for (const Window& w : windows) {
    if (w.missing.empty()) {
      write_row(w);
    } else {
      out << indent << w.missing << "\n";
    }
  }
}

void writeSetpoints(const FlightReport& r, std::ostream& out) {
  if (r.setpoints.empty()) return;
  char line[512];
  const std::string settle = "settle (<" + formatQuantity(r.settle_error, "m") + ")";
  std::snprintf(line, sizeof line, "  setpoint            size    %-14s  overshoot  steady error\n", settle.c_str());
  out << line;
  writeWindows(r.setpoints, "  ", out, [&](const SetpointWindow& w) {
    std::snprintf(line, sizeof line, "  %-18s %5.2f m  %-14s  %7s  %s\n", w.label.c_str(), w.size,
                  format("%.2f s", w.settle_time).c_str(), w.is_jump ? format("%.1f %%", 100.0 * w.overshoot).c_str() : "-",
                  format("%.1f cm", 100.0 * w.steady_error).c_str());
    out << line;
  });
}

void writePulls(const FlightReport& r, std::ostream& out) {
  char line[512];
  writeWindows(r.pulls, "  ", out, [&](const PullWindow& p) {
    std::snprintf(line, sizeof line, "  %-18s %s: pushed %.2f m away, back within %s after %s, %.0f %% past the setpoint\n",
                  p.label.c_str(), describeDisturbance(p.disturbance).c_str(), p.max_deviation,
                  formatQuantity(r.return_error, "m").c_str(), format("%.2f s", p.return_time).c_str(),
                  100.0 * p.return_overshoot);
    out << line;
  });
}

void writeTrajectories(const FlightReport& r, std::ostream& out) {
  char line[512];
  writeWindows(r.trajectories, "  ", out, [&](const PathTrackingReport& t) {
    std::snprintf(line, sizeof line, "  %s (%s, %s, %d samples, %.2f m per lap): %s%s, %.2f laps\n", t.label.c_str(),
                  t.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial", t.closed ? "closed" : "open",
                  t.samples, t.path_length, t.entry_time > 0.0 ? format("entered in %.2f s, ", t.entry_time).c_str() : "",
                  t.completed ? format("completed in %.2f s", t.completion_time).c_str()
                              : format("not completed (%.2f m left)", t.remaining).c_str(),
                  t.laps);
    out << line;
    if (std::isfinite(t.aborted_at)) out << format("    aborted into a hold by the guard at %.2f s\n", t.aborted_at);
    std::snprintf(line, sizeof line,
                  "    path error RMS %.3f m (x %.3f y %.3f z %.3f), max %.3f m; time-indexed RMS %.3f m, max %.3f m\n",
                  t.path_error_rms, t.path_error_rms_axis[0], t.path_error_rms_axis[1], t.path_error_rms_axis[2],
                  t.path_error_max, t.time_error_rms, t.time_error_max);
    out << line;
    std::snprintf(line, sizeof line,
                  "    samples passed %d, skipped %zu (worst visited %.2f m); saturation %.1f %% (rate %.1f %%, thrust "
                  "%.1f %%), thrust %.2f..%.2f m/s^2, %lld outside limits\n",
                  t.samples_passed, t.skipped.size(), t.worst_visit, t.saturation_percent, t.rate_saturation_percent,
                  t.thrust_saturation_percent, t.thrust_min, t.thrust_max, static_cast<long long>(t.thrust_violations));
    out << line;
    writeWindows(t.pulls, "    ", out, [&](const PathPull& p) {
      std::snprintf(line, sizeof line, "    %s at %.2f s for %.2f s: %.2f m off the path at release, back on it after %s\n",
                    p.label.c_str(), p.start, p.release - p.start, p.distance_at_release, format("%.2f s", p.return_time).c_str());
      out << line;
    });
  });
}

// Recovery from an airborne start or a throw, and trajectories the guard aborted.
void writeStressors(const FlightReport& r, std::ostream& out) {
  char line[512];
  if (r.recovery) {
    const RecoveryReport& v = *r.recovery;
    std::snprintf(line, sizeof line,
                  "  recovery from %s at %.2f s (tilt %.0f deg): level after %s, height lost %.2f m, settled after %s\n",
                  v.throw_start ? "a throw" : "an airborne start", v.start, v.initial_tilt_deg,
                  format("%.2f s", v.level_time).c_str(), v.height_lost, format("%.2f s", v.settle_time).c_str());
    out << line;
    if (v.throw_start) {
      std::snprintf(line, sizeof line, "  throw released at %.2f s, detected after %s\n", v.release,
                    format("%.3f s", v.detect_delay).c_str());
      out << line;
    }
  }
  if (r.trajectory_aborts > 0) {
    std::snprintf(line, sizeof line, "  trajectories aborted into a hold by the guard: %lld\n",
                  static_cast<long long>(r.trajectory_aborts));
    out << line;
  }
}

void writeMeasurements(const FlightReport& r, std::ostream& out) {
  char line[512];
  std::snprintf(line, sizeof line, "  estimator (hover): position %s RMS, attitude %s RMS (whole flight %s, %s)\n",
                format("%.2f cm", 100.0 * r.estimator.position_rms).c_str(),
                format("%.2f deg", r.estimator.attitude_rms_deg).c_str(),
                format("%.2f cm", 100.0 * r.estimator.position_rms_all).c_str(),
                format("%.2f deg", r.estimator.attitude_rms_deg_all).c_str());
  out << line;
  std::snprintf(line, sizeof line, "  rates: IMU %.1f Hz, STATE_EST %.1f Hz, RATE_CMD %.1f Hz, GAINS %.2f Hz\n",
                r.imu_rate_hz, r.state_est_rate_hz, r.rate_cmd_rate_hz, r.gains_rate_hz);
  out << line;
  std::snprintf(line, sizeof line, "  gain solve: median %.1f us, p99 %.1f us, max %.1f us; %g doublings (median)\n",
                r.solve_us.median, r.solve_us.p99, r.solve_us.max, r.iterations.median);
  out << line;
  std::snprintf(line, sizeof line, "  controller period (sim time): median %.2f ms, |jitter| p99 %.2f ms\n",
                r.rate_cmd_period_ms.median, r.rate_cmd_jitter_ms.p99);
  out << line;
  if (r.state_to_command_us.count > 0 && !r.processes.empty()) {
    std::snprintf(line, sizeof line, "  STATE_EST -> RATE_CMD at the recorder: median %.0f us, p99 %.0f us\n",
                  r.state_to_command_us.median, r.state_to_command_us.p99);
    out << line;
    std::snprintf(line, sizeof line, "  controller period (wall clock) beyond its STATE_EST's: |jitter| median %.0f us, p99 %.0f us\n",
                  r.rate_cmd_wall_jitter_us.median, r.rate_cmd_wall_jitter_us.p99);
    out << line;
  }
  std::snprintf(line, sizeof line,
                "  saturation (airborne): %lld of %lld thrust demands outside [c_min, c_max] (demand %.2f .. %.2f "
                "m/s^2), %lld of %lld rotor commands at a rotor limit\n",
                static_cast<long long>(r.saturation.thrust_demand_outside), static_cast<long long>(r.saturation.commands),
                r.saturation.thrust_demand_min, r.saturation.thrust_demand_max,
                static_cast<long long>(r.saturation.rotor_at_limit), static_cast<long long>(r.saturation.motor_commands));
  out << line;
  if (!r.processes.empty()) {
    out << "  CPU (% of one core, airborne mean):";
    for (const ProcessLoad& p : r.processes) {
      std::snprintf(line, sizeof line, " %s %.1f", p.process.c_str(), p.cpu_percent_mean);
      out << line;
    }
    std::snprintf(line, sizeof line, "; flight stack %.1f\n", r.stack_cpu_percent);
    out << line;
  }
  writeLossSummary(r, out);
  if (r.calibration) {
    const calibrate::Calibration& c = *r.calibration;
    std::snprintf(line, sizeof line,
                  "  this machine (1 kHz ping/pong before the flight): round trip median %.0f us, p99 %.0f us, CPU "
                  "%.1f %%; the flight stack used %.2fx that CPU; over the one-way median its latency median was %.2fx "
                  "and its wall-clock jitter median %.2fx; over the one-way p99 (reported only) its latency p99 "
                  "%.2fx and its jitter p99 %.2fx\n",
                  c.rtt_median_us, c.rtt_p99_us, c.cpu_percent, r.stack_cpu_relative, r.state_to_command_relative,
                  r.rate_cmd_wall_jitter_relative, r.state_to_command_p99_relative, r.rate_cmd_wall_jitter_p99_relative);
    out << line;
  }
  std::snprintf(line, sizeof line, "  max tilt %.1f deg, touchdown %.2f m/s%s, non-finite messages %lld\n", r.max_tilt_deg,
                r.touchdown_speed, r.crashed ? ", CRASHED" : "", static_cast<long long>(r.nonfinite));
  out << line;
}

std::string formatLimit(const Check& c) {
  return std::string(c.upper ? "<= " : ">= ") + formatQuantity(c.limit, c.unit);
}

// One line per check: verdict, what is judged, the window, the value and the limit.
void writeCheckTable(const FlightReport& r, std::ostream& out) {
  size_t width = 10;
  for (const Check& c : r.checks) width = std::max(width, c.description.size());
  out << "  checks:\n";
  char line[768];
  for (const Check& c : r.checks) {
    std::snprintf(line, sizeof line, "    %-4s %-*s  %-14s %10s  %s\n", c.pass ? "ok" : "FAIL", static_cast<int>(width),
                  c.description.c_str(), c.window.c_str(), formatQuantity(c.value, c.unit).c_str(),
                  formatLimit(c).c_str());
    out << line;
  }
  for (const NotJudged& n : r.not_judged) out << "    --   " << n.key << " not judged: " << n.reason << "\n";
}

}  // namespace

void writeSummary(const FlightReport& r, std::ostream& out) {
  int passed = 0;
  for (const Check& c : r.checks) passed += c.pass ? 1 : 0;
  char line[512];
  std::snprintf(line, sizeof line, "scenario %s: %s (%d of %zu checks pass)\n", r.scenario.c_str(),
                r.passed() ? "PASS" : "FAIL", passed, r.checks.size());
  out << line;
  writeSetpoints(r, out);
  writePulls(r, out);
  writeTrajectories(r, out);
  writeStressors(r, out);
  writeMeasurements(r, out);
  writeCheckTable(r, out);
  for (const Check& c : r.checks) {
    if (c.pass) continue;
    out << "  FAILED " << c.name << ": " << formatQuantity(c.value, c.unit) << " (limit " << formatLimit(c) << ")";
    out << (c.note.empty() ? "" : ": " + c.note) << "\n";
  }
  if (r.checks.empty()) out << "  FAILED: no check judged this flight\n";
}

}  // namespace sdlqr::analysis
