// What a flight measured beyond its windows: the truth's extremes, estimator accuracy, rates,
// timing, bus latency and the load of every process.

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "flight_parts.hpp"
#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::analysis::detail {

namespace {

double attitudeErrorDeg(const Quat& a, const Quat& b) {
  const double w = std::min(1.0, std::abs(a.normalized().dot(b.normalized())));
  return 2.0 * std::acos(w) * 180.0 / M_PI;
}

bool finiteMessage(const StateEstimate& m) {
  return m.position.allFinite() && m.orientation.allFinite() && m.velocity.allFinite() && m.body_rate.allFinite();
}
bool finiteMessage(const RateCommand& m) { return m.body_rate.allFinite() && std::isfinite(m.thrust); }
bool finiteMessage(const GainSet& m) { return m.K.allFinite() && m.x_lin.allFinite() && m.u_lin.allFinite(); }

template <class T>
int64_t countNonFinite(const logger::Series<T>& series) {
  int64_t count = 0;
  for (const T& m : series.messages) count += finiteMessage(m) ? 0 : 1;
  return count;
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

// Each STATE_EST seq's receive time at the recorder (the last one when a seq repeats), looked up
// by seq: sorted once, searched by halves (a flight holds 13,000 of them).
class StateReceiveTimes {
 public:
  explicit StateReceiveTimes(const logger::FlightLog& log) {
    times_.reserve(log.state_estimate.size());
    for (size_t i = 0; i < log.state_estimate.size(); ++i) {
      times_.emplace_back(log.state_estimate[i].seq, log.state_estimate.receive_utime[i]);
    }
    // Stable: of equal seqs the last received stays last; keep only it.
    std::stable_sort(times_.begin(), times_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<int64_t, int64_t>> unique;
    unique.reserve(times_.size());
    for (const auto& t : times_) {
      if (!unique.empty() && unique.back().first == t.first) unique.back() = t;
      else unique.push_back(t);
    }
    times_.swap(unique);
  }
  const int64_t* find(int64_t seq) const {
    const auto it = std::lower_bound(times_.begin(), times_.end(), seq, [](const auto& t, int64_t s) { return t.first < s; });
    return it != times_.end() && it->first == seq ? &it->second : nullptr;
  }

 private:
  std::vector<std::pair<int64_t, int64_t>> times_;
};

// STATE_EST publish -> RATE_CMD computed from it, both as the recorder received them [us].
std::vector<double> stateToCommandLatency(const logger::FlightLog& log, const StateReceiveTimes& state_receive) {
  std::vector<double> latency;
  for (size_t i = 0; i < log.rate_command.size(); ++i) {
    const int64_t* received = state_receive.find(log.rate_command[i].state_seq);
    if (received) latency.push_back(static_cast<double>(log.rate_command.receive_utime[i] - *received));
  }
  return latency;
}

// The controller's wall-clock period against its input's: for consecutive RATE_CMDs while
// airborne (one second trimmed at each end), |their receive interval - the receive interval of the
// STATE_ESTs they answer| at the recorder [us]. The simulator's own pacing (which a busy machine
// bunches) drops out; what remains is what the controller and the bus add to the period.
std::vector<double> wallJitterUs(const logger::FlightLog& log, const FlightReport& report,
                                 const StateReceiveTimes& state_receive) {
  std::vector<double> jitter;
  if (!std::isfinite(report.flight_start)) return jitter;
  const double a = report.flight_start + 1.0, b = report.flight_end - 1.0;
  for (size_t i = 1; i < log.rate_command.size(); ++i) {
    const double t = seconds(log.rate_command[i].utime);
    const int64_t* now = state_receive.find(log.rate_command[i].state_seq);
    const int64_t* before = state_receive.find(log.rate_command[i - 1].state_seq);
    if (t < a || t > b || !now || !before) continue;
    const int64_t command_interval = log.rate_command.receive_utime[i] - log.rate_command.receive_utime[i - 1];
    jitter.push_back(std::abs(static_cast<double>(command_interval - (*now - *before))));
  }
  return jitter;
}

bool rotorAtLimit(const MotorCommand& m, double low, double high) {
  constexpr double kTolerance = 1e-6;  // [N] far below any rotor's resolution, above round-off
  for (int i = 0; i < 4; ++i) {
    if (!(m.thrust[i] > low + kTolerance && m.thrust[i] < high - kTolerance)) return true;
  }
  return false;
}

}  // namespace

bool thrustDemandOutside(const RateCommand& c, double c_min, double c_max) {
  return !(c.thrust_demand >= c_min && c.thrust_demand <= c_max) || !std::isfinite(c.thrust) ||
         !c.body_rate.allFinite();
}

Saturation measureSaturation(const logger::FlightLog& log, const AnalysisOptions& options, double start, double end) {
  Saturation s;
  for (const RateCommand& c : log.rate_command.messages) {
    const double t = seconds(c.utime);
    if (t < start || t > end) continue;
    ++s.commands;
    s.thrust_demand_outside += thrustDemandOutside(c, options.path.thrust_min, options.path.thrust_max) ? 1 : 0;
    if (!std::isfinite(c.thrust_demand)) continue;
    s.thrust_demand_min = std::isfinite(s.thrust_demand_min) ? std::min(s.thrust_demand_min, c.thrust_demand) : c.thrust_demand;
    s.thrust_demand_max = std::isfinite(s.thrust_demand_max) ? std::max(s.thrust_demand_max, c.thrust_demand) : c.thrust_demand;
  }
  for (const MotorCommand& m : log.motor_command.messages) {
    const double t = seconds(m.utime);
    if (t < start || t > end || m.mode != MotorMode::kRate) continue;
    ++s.motor_commands;
    s.rotor_at_limit += rotorAtLimit(m, options.rotor_thrust_min, options.rotor_thrust_max) ? 1 : 0;
  }
  return s;
}

void summarizeTruth(const logger::FlightLog& log, FlightReport& report) {
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
}

EstimatorAccuracy estimatorAccuracy(const logger::FlightLog& log) {
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
    if (a.velocity.norm() < 0.3) {  // hover
      sum_p += ep * ep;
      sum_a += ea * ea;
      ++n;
    }
  }
  EstimatorAccuracy accuracy;
  accuracy.samples = n;
  if (n > 0) {
    accuracy.position_rms = std::sqrt(sum_p / static_cast<double>(n));
    accuracy.attitude_rms_deg = std::sqrt(sum_a / static_cast<double>(n));
  }
  if (n_all > 0) {
    accuracy.position_rms_all = std::sqrt(sum_p_all / static_cast<double>(n_all));
    accuracy.attitude_rms_deg_all = std::sqrt(sum_a_all / static_cast<double>(n_all));
    accuracy.position_max_all = max_p;
  }
  return accuracy;
}

void measureTiming(const logger::FlightLog& log, const AnalysisOptions& options, FlightReport& report) {
  // Rates over the airborne span (one second trimmed at each end for start-up and landing).
  if (std::isfinite(report.flight_start)) {
    const double a = report.flight_start + 1.0, b = report.flight_end - 1.0;
    report.imu_rate_hz = rateIn(log.imu, a, b);
    report.state_est_rate_hz = rateIn(log.state_estimate, a, b);
    report.rate_cmd_rate_hz = rateIn(log.rate_command, a, b);
    report.gains_rate_hz = rateIn(log.gains, a, b);
  }
  std::vector<double> solve, iterations, period, jitter;
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
  report.solve_us = tables::describe(solve);
  report.iterations = tables::describe(iterations);
  report.rate_cmd_period_ms = tables::describe(period);
  report.rate_cmd_jitter_ms = tables::describe(jitter);
  const StateReceiveTimes state_receive(log);
  report.rate_cmd_wall_jitter_us = tables::describe(wallJitterUs(log, report, state_receive));
  report.state_to_command_us = tables::describe(stateToCommandLatency(log, state_receive));
  report.nonfinite = countNonFinite(log.state_estimate) + countNonFinite(log.rate_command) + countNonFinite(log.gains);
}

void measureLoad(const logger::FlightLog& log, FlightReport& report) {
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
  if (report.calibration && !report.processes.empty()) {
    report.stack_cpu_relative = report.stack_cpu_percent / report.calibration->cpu_percent;
  }
  if (report.calibration && report.state_to_command_us.count > 0) {
    report.state_to_command_relative = report.state_to_command_us.median / report.calibration->oneWayMedianUs();
    report.state_to_command_p99_relative = report.state_to_command_us.p99 / report.calibration->oneWayP99Us();
  }
  if (report.calibration && report.rate_cmd_wall_jitter_us.count > 0) {
    report.rate_cmd_wall_jitter_relative = report.rate_cmd_wall_jitter_us.median / report.calibration->oneWayMedianUs();
    report.rate_cmd_wall_jitter_p99_relative = report.rate_cmd_wall_jitter_us.p99 / report.calibration->oneWayP99Us();
  }
}

}  // namespace sdlqr::analysis::detail
