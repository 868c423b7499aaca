#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/logger/json_writer.hpp"

namespace sdlqr::analysis {

namespace {

void writeDistribution(logger::JsonWriter& json, const char* name, const logger::Distribution& d) {
  json.key(name);
  json.beginObject();
  json.memberInt("count", d.count);
  json.member("mean", d.mean);
  json.member("min", d.min);
  json.member("median", d.median);
  json.member("p99", d.p99);
  json.member("max", d.max);
  json.endObject();
}

void writeVec3(logger::JsonWriter& json, const char* name, const Vec3& v) {
  json.key(name);
  json.beginArray();
  for (int i = 0; i < 3; ++i) json.number(v[i]);
  json.endArray();
}

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

void writeChecks(logger::JsonWriter& json, const FlightReport& r) {
  json.key("checks");
  json.beginArray();
  for (const Check& c : r.checks) {
    json.beginObject();
    json.member("name", c.name);
    json.member("key", c.key);
    json.member("window", c.window);
    json.member("description", c.description);
    json.member("unit", c.unit);
    json.member("value", c.value);
    json.member("limit", c.limit);
    json.member("rule", c.upper ? "<=" : ">=");
    json.memberBool("pass", c.pass);
    if (!c.note.empty()) json.member("note", c.note);
    json.endObject();
  }
  json.endArray();
  json.key("not_judged");
  json.beginArray();
  for (const NotJudged& n : r.not_judged) {
    json.beginObject();
    json.member("key", n.key);
    json.member("reason", n.reason);
    json.endObject();
  }
  json.endArray();
}

// The scenario's events as the log had them, and the touchdown after each LAND.
void writeEvents(logger::JsonWriter& json, const FlightReport& r) {
  json.key("events");
  json.beginArray();
  for (const ExpectedEvent& e : r.events) {
    json.beginObject();
    json.member("label", e.label);
    json.member("channel", e.channel);
    json.member("at_s", e.at);
    json.memberBool("in_log", e.found());
    json.member("seen_s", e.seen);
    json.endObject();
  }
  json.endArray();
  json.key("landings");
  json.beginArray();
  for (const Landing& l : r.landings) {
    json.beginObject();
    json.member("label", l.label);
    json.member("start_s", l.start);
    json.member("touchdown_s", l.touchdown);
    json.member("touchdown_speed_mps", l.touchdown_speed);
    json.endObject();
  }
  json.endArray();
}

void writeCalibration(logger::JsonWriter& json, const FlightReport& r) {
  if (!r.calibration) return;
  const calibrate::Calibration& c = *r.calibration;
  json.key("calibration");
  json.beginObject();
  json.member("echo_rate_hz", c.echo_rate_hz);
  json.member("rtt_median_us", c.rtt_median_us);
  json.member("rtt_p99_us", c.rtt_p99_us);
  json.member("cpu_percent", c.cpu_percent);
  json.member("host", c.host);
  json.member("date", c.date);
  json.endObject();
  json.member("stack_cpu_relative", r.stack_cpu_relative);
  json.member("state_to_command_relative", r.state_to_command_relative);
}

}  // namespace

void writeJson(const FlightReport& r, std::ostream& out) {
  logger::JsonWriter json(out);
  json.beginObject();
  json.member("scenario", r.scenario);
  json.memberBool("passed", r.passed());
  json.member("flight_start_s", r.flight_start);
  json.member("flight_end_s", r.flight_end);
  writeEvents(json, r);
  json.key("setpoints");
  json.beginArray();
  for (const SetpointWindow& w : r.setpoints) {
    json.beginObject();
    json.member("label", w.label);
    json.memberBool("jump", w.is_jump);
    json.member("start_s", w.start);
    json.member("end_s", w.end);
    writeVec3(json, "from_m", w.from);
    writeVec3(json, "to_m", w.to);
    json.member("size_m", w.size);
    json.member("settle_time_s", w.settle_time);
    json.member("overshoot", w.overshoot);
    json.member("steady_error_m", w.steady_error);
    json.member("max_error_after_settle_m", w.max_error_after_settle);
    json.endObject();
  }
  json.endArray();
  json.key("pulls");
  json.beginArray();
  for (const PullWindow& p : r.pulls) {
    json.beginObject();
    json.member("label", p.label);
    json.member("start_s", p.start);
    json.member("release_s", p.release);
    json.member("kind", disturbanceKind(p.disturbance));
    writeVec3(json, "force_n", p.disturbance.force);
    writeVec3(json, "torque_nm", p.disturbance.torque);
    if (p.disturbance.mode == DisturbanceMode::kHold) {
      writeVec3(json, "hold_position_m", p.disturbance.hold_position);
      json.member("hold_stiffness_n_per_m", p.disturbance.hold_stiffness);
    }
    writeVec3(json, "setpoint_m", p.setpoint);
    json.member("max_deviation_m", p.max_deviation);
    json.member("return_time_s", p.return_time);
    json.member("return_overshoot", p.return_overshoot);
    json.endObject();
  }
  json.endArray();
  json.key("trajectories");
  json.beginArray();
  for (const PathTrackingReport& t : r.trajectories) {
    json.beginObject();
    json.member("label", t.label);
    json.memberInt("trajectory_seq", t.trajectory_seq);
    json.member("tracking", t.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial");
    json.memberBool("closed", t.closed);
    json.memberInt("samples", t.samples);
    json.member("path_length_m", t.path_length);
    json.member("duration_s", t.duration);
    json.member("start_s", t.start);
    json.member("end_s", t.end);
    json.memberBool("completed", t.completed);
    json.member("completion_time_s", t.completion_time);
    json.member("remaining_m", t.remaining);
    json.member("laps", t.laps);
    json.memberInt("truth_samples", t.truth_samples);
    json.member("path_error_rms_m", t.path_error_rms);
    json.member("path_error_max_m", t.path_error_max);
    writeVec3(json, "path_error_rms_axis_m", t.path_error_rms_axis);
    writeVec3(json, "path_error_max_axis_m", t.path_error_max_axis);
    json.member("time_error_rms_m", t.time_error_rms);
    json.member("time_error_max_m", t.time_error_max);
    json.memberInt("samples_passed", t.samples_passed);
    json.memberInt("samples_skipped", static_cast<int64_t>(t.skipped.size()));
    json.member("worst_visit_m", t.worst_visit);
    json.key("skipped");
    json.beginArray();
    for (const SkippedSample& k : t.skipped) {
      json.beginObject();
      json.memberInt("lap", k.lap);
      json.memberInt("index", k.index);
      json.member("arc_m", k.arc);
      json.member("closest_m", k.closest);
      json.endObject();
    }
    json.endArray();
    json.memberInt("commands", t.commands);
    json.member("saturation_percent", t.saturation_percent);
    json.member("rate_saturation_percent", t.rate_saturation_percent);
    json.member("thrust_saturation_percent", t.thrust_saturation_percent);
    json.member("thrust_min", t.thrust_min);
    json.member("thrust_max", t.thrust_max);
    json.memberInt("thrust_violations", t.thrust_violations);
    json.key("pulls");
    json.beginArray();
    for (const PathPull& p : t.pulls) {
      json.beginObject();
      json.member("start_s", p.start);
      json.member("release_s", p.release);
      json.member("max_distance_m", p.max_distance);
      json.member("distance_at_release_m", p.distance_at_release);
      json.member("return_time_s", p.return_time);
      json.endObject();
    }
    json.endArray();
    json.endObject();
  }
  json.endArray();
  json.key("estimator");
  json.beginObject();
  json.memberInt("hover_samples", r.estimator.samples);
  json.member("position_rms_m", r.estimator.position_rms);
  json.member("attitude_rms_deg", r.estimator.attitude_rms_deg);
  json.member("position_rms_all_m", r.estimator.position_rms_all);
  json.member("attitude_rms_all_deg", r.estimator.attitude_rms_deg_all);
  json.member("position_max_all_m", r.estimator.position_max_all);
  json.endObject();
  json.key("rates_hz");
  json.beginObject();
  json.member("IMU", r.imu_rate_hz);
  json.member("STATE_EST", r.state_est_rate_hz);
  json.member("RATE_CMD", r.rate_cmd_rate_hz);
  json.member("GAINS", r.gains_rate_hz);
  json.endObject();
  writeDistribution(json, "gains_solve_us", r.solve_us);
  writeDistribution(json, "gains_iterations", r.iterations);
  writeDistribution(json, "rate_cmd_period_ms", r.rate_cmd_period_ms);
  writeDistribution(json, "rate_cmd_jitter_ms", r.rate_cmd_jitter_ms);
  writeDistribution(json, "state_est_to_rate_cmd_us", r.state_to_command_us);
  writeDistribution(json, "rate_cmd_wall_jitter_us", r.rate_cmd_wall_jitter_us);
  json.key("saturation");
  json.beginObject();
  json.memberInt("rate_commands", r.saturation.commands);
  json.memberInt("thrust_demand_outside", r.saturation.thrust_demand_outside);
  json.member("thrust_demand_min", r.saturation.thrust_demand_min);
  json.member("thrust_demand_max", r.saturation.thrust_demand_max);
  json.memberInt("motor_commands", r.saturation.motor_commands);
  json.memberInt("rotor_at_limit", r.saturation.rotor_at_limit);
  json.endObject();
  json.key("processes");
  json.beginArray();
  for (const ProcessLoad& p : r.processes) {
    json.beginObject();
    json.member("process", p.process);
    json.member("cpu_percent_mean", p.cpu_percent_mean);
    json.member("cpu_percent_max", p.cpu_percent_max);
    json.memberInt("rejected", p.rejected);
    json.memberInt("dropped", p.dropped);
    json.memberInt("deadline_misses", p.deadline_misses);
    json.memberInt("errors", p.errors);
    json.endObject();
  }
  json.endArray();
  json.key("message_loss");
  json.beginArray();
  for (const ChannelLoss& l : r.message_loss) {
    json.beginObject();
    json.member("process", l.process);
    json.member("channel", l.channel);
    json.memberInt("lost", l.lost);
    json.memberInt("queue_dropped", l.queue_dropped);
    json.endObject();
  }
  json.endArray();
  json.member("stack_cpu_percent", r.stack_cpu_percent);
  writeCalibration(json, r);
  json.memberInt("nonfinite_messages", r.nonfinite);
  json.member("max_tilt_deg", r.max_tilt_deg);
  json.member("touchdown_speed_mps", r.touchdown_speed);
  json.memberBool("crashed", r.crashed);
  writeChecks(json, r);
  json.endObject();
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

void writeSetpoints(const FlightReport& r, std::ostream& out) {
  if (r.setpoints.empty()) return;
  char line[512];
  const std::string settle = "settle (<" + formatQuantity(r.settle_error, "m") + ")";
  std::snprintf(line, sizeof line, "  setpoint            size    %-14s  overshoot  steady error\n", settle.c_str());
  out << line;
  for (const SetpointWindow& w : r.setpoints) {
    if (!w.missing.empty()) {
      out << "  " << w.missing << "\n";
      continue;
    }
    std::snprintf(line, sizeof line, "  %-18s %5.2f m  %-14s  %7s  %s\n", w.label.c_str(), w.size,
                  format("%.2f s", w.settle_time).c_str(), w.is_jump ? format("%.1f %%", 100.0 * w.overshoot).c_str() : "-",
                  format("%.1f cm", 100.0 * w.steady_error).c_str());
    out << line;
  }
}

void writePulls(const FlightReport& r, std::ostream& out) {
  char line[512];
  for (const PullWindow& p : r.pulls) {
    if (!p.missing.empty()) {
      out << "  " << p.missing << "\n";
      continue;
    }
    std::snprintf(line, sizeof line, "  %-18s %s: pushed %.2f m away, back within %s after %s, %.0f %% past the setpoint\n",
                  p.label.c_str(), describeDisturbance(p.disturbance).c_str(), p.max_deviation,
                  formatQuantity(r.return_error, "m").c_str(), format("%.2f s", p.return_time).c_str(),
                  100.0 * p.return_overshoot);
    out << line;
  }
}

void writeTrajectories(const FlightReport& r, std::ostream& out) {
  char line[512];
  for (const PathTrackingReport& t : r.trajectories) {
    if (!t.missing.empty()) {
      out << "  " << t.missing << "\n";
      continue;
    }
    std::snprintf(line, sizeof line, "  %s (%s, %s, %d samples, %.2f m per lap): %s, %.2f laps\n", t.label.c_str(),
                  t.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial", t.closed ? "closed" : "open",
                  t.samples, t.path_length,
                  t.completed ? format("completed in %.2f s", t.completion_time).c_str()
                              : format("not completed (%.2f m left)", t.remaining).c_str(),
                  t.laps);
    out << line;
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
    for (const PathPull& p : t.pulls) {
      if (!p.missing.empty()) {
        out << "    " << p.missing << "\n";
        continue;
      }
      std::snprintf(line, sizeof line, "    %s at %.2f s for %.2f s: %.2f m off the path at release, back on it after %s\n",
                    p.label.c_str(), p.start, p.release - p.start, p.distance_at_release, format("%.2f s", p.return_time).c_str());
      out << line;
    }
  }
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
