#include "sdlqr/faults/outage_check.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::faults {

namespace {

constexpr double kRadToDeg = 180.0 / M_PI;

// Index of the last message received before `wall_utime`, or -1.
template <class T>
std::ptrdiff_t lastReceivedBefore(const logger::Series<T>& series, int64_t wall_utime) {
  std::ptrdiff_t found = -1;
  for (size_t i = 0; i < series.size(); ++i) {
    if (series.receive_utime[i] < wall_utime) found = static_cast<std::ptrdiff_t>(i);
  }
  return found;
}

// Index of the killed process's last message: the last received before its restart. Judged from
// the kill instead, a message sent just before it and heard by the recorder just after (a loaded
// machine) was missed: a CI run found the gains fallback 0.1 s "late", from the GAINS before. (The
// estimator's and the controller's outages still take the last received before the kill: there
// the same race moves the judged delay by one message, 4 and 10 ms, against limits of 0.2 s.)
template <class T>
std::ptrdiff_t lastSentBeforeTheKill(const logger::Series<T>& series, int64_t restart_wall) {
  return lastReceivedBefore(series, restart_wall);
}

template <class T>
std::ptrdiff_t firstReceivedAtOrAfter(const logger::Series<T>& series, int64_t wall_utime) {
  for (size_t i = 0; i < series.size(); ++i) {
    if (series.receive_utime[i] >= wall_utime) return static_cast<std::ptrdiff_t>(i);
  }
  return -1;
}

int64_t firstFailsafeAfter(const logger::FlightLog& log, int64_t utime) {
  for (const MotorCommand& motor : log.motor_command.messages) {
    if (motor.utime >= utime && motor.mode == MotorMode::kFailsafe) return motor.utime;
  }
  return -1;
}

double seconds(int64_t us) { return static_cast<double>(us) * 1e-6; }

// Recorder receive time of the first HEARTBEAT of `process` at or after `wall_utime`, or -1.
int64_t firstHeartbeatAtOrAfter(const logger::FlightLog& log, const std::string& process, int64_t wall_utime) {
  for (size_t i = 0; i < log.heartbeat.size(); ++i) {
    if (log.heartbeat[i].process == process && log.heartbeat.receive_utime[i] >= wall_utime) {
      return log.heartbeat.receive_utime[i];
    }
  }
  return -1;
}

// COMMAND TAKEOFFs received at or after `wall_utime` whose seq was received before: re-sent.
int64_t resentTakeoffsAfter(const logger::FlightLog& log, int64_t wall_utime) {
  std::set<int64_t> seen;
  int64_t resent = 0;
  for (size_t i = 0; i < log.command.size(); ++i) {
    const Command& c = log.command[i];
    if (c.command != CommandType::kTakeoff) continue;
    const bool again = !seen.insert(c.seq).second;
    if (again && log.command.receive_utime[i] >= wall_utime) ++resent;
  }
  return resent;
}

}  // namespace

int64_t simTimeAtWall(const logger::FlightLog& log, int64_t wall_utime) {
  const std::ptrdiff_t i = firstReceivedAtOrAfter(log.sim_truth, wall_utime);
  return i < 0 ? -1 : log.sim_truth[static_cast<size_t>(i)].utime;
}

GainsOutage measureGainsOutage(const logger::FlightLog& log, int64_t kill_wall, int64_t restart_wall,
                               double fallback_timeout_s) {
  GainsOutage out;
  const std::ptrdiff_t last = lastSentBeforeTheKill(log.gains, restart_wall);
  if (last >= 0) out.last_gains_utime = log.gains[static_cast<size_t>(last)].utime;
  const std::ptrdiff_t resumed = firstReceivedAtOrAfter(log.gains, restart_wall);
  if (resumed >= 0) out.resume_delay_s = seconds(log.gains.receive_utime[static_cast<size_t>(resumed)] - restart_wall);
  const int64_t up_wall = firstHeartbeatAtOrAfter(log, "sdlqr-gains", restart_wall);
  const int64_t up_utime = up_wall < 0 ? -1 : simTimeAtWall(log, up_wall);
  if (resumed >= 0 && up_utime >= 0) {
    out.resume_after_up_s = seconds(log.gains[static_cast<size_t>(resumed)].utime - up_utime);
  }
  // One controller tick of slack past the timeout: the tick that crosses it may still use the K.
  const int64_t timeout_utime = out.last_gains_utime + static_cast<int64_t>((fallback_timeout_s + 0.01) * 1e6);
  for (size_t i = 0; i < log.rate_command.size(); ++i) {
    const RateCommand& command = log.rate_command[i];
    const int64_t received = log.rate_command.receive_utime[i];
    if (received < kill_wall) continue;
    const bool fallback = command.gains_status == GainsFreshness::kFallback;
    if (received < restart_wall) {
      if (fallback) {
        ++out.fallback_commands;
        if (out.first_fallback_utime < 0) out.first_fallback_utime = command.utime;
      } else if (out.last_gains_utime >= 0 && command.utime > timeout_utime) {
        ++out.late_non_fallback_commands;
      }
    } else if (command.gains_status == GainsFreshness::kFresh && command.gains_seq >= 0 && resumed >= 0 &&
               received >= log.gains.receive_utime[static_cast<size_t>(resumed)]) {
      ++out.fresh_commands_after_resume;
    }
  }
  return out;
}

EstimatorOutage measureEstimatorOutage(const logger::FlightLog& log, int64_t kill_wall, int64_t restart_wall) {
  EstimatorOutage out;
  const std::ptrdiff_t last = lastReceivedBefore(log.state_estimate, kill_wall);
  if (last < 0) return out;
  out.last_estimate_utime = log.state_estimate[static_cast<size_t>(last)].utime;
  out.failsafe_utime = firstFailsafeAfter(log, out.last_estimate_utime);
  if (out.failsafe_utime >= 0) out.failsafe_delay_s = seconds(out.failsafe_utime - out.last_estimate_utime);
  int64_t end_utime = simTimeAtWall(log, restart_wall);
  if (end_utime < 0) end_utime = log.sim_truth.empty() ? 0 : log.sim_truth.back().utime;
  const SimTruth* previous = nullptr;
  for (const SimTruth& truth : log.sim_truth.messages) {
    if (truth.utime < out.last_estimate_utime || truth.utime > end_utime) continue;
    out.crashed = out.crashed || truth.crashed;
    out.max_tilt_deg = std::max(out.max_tilt_deg, quat::tilt(truth.orientation) * kRadToDeg);
    if (out.touchdown_utime < 0 && truth.on_ground && previous != nullptr && !previous->on_ground) {
      out.touchdown_utime = truth.utime;
      out.touchdown_speed = previous->velocity.norm();
    }
    previous = &truth;
  }
  if (out.touchdown_utime >= 0) {
    for (const MotorCommand& motor : log.motor_command.messages) {
      if (motor.utime >= out.touchdown_utime && motor.utime <= end_utime && motor.mode == MotorMode::kDisarmed) {
        out.disarmed_after_touchdown = true;
        out.disarm_utime = motor.utime;
        break;
      }
    }
  }
  if (out.disarm_utime >= 0) {
    for (const MotorCommand& motor : log.motor_command.messages) {
      if (motor.utime > out.disarm_utime && (motor.armed || motor.mode != MotorMode::kDisarmed)) ++out.rearmed_commands;
    }
  }
  out.resent_takeoffs_after_restart = resentTakeoffsAfter(log, restart_wall);
  return out;
}

std::vector<Finding> judgeEstimatorOutage(const EstimatorOutage& e, const EstimatorLimits& limits) {
  std::vector<Finding> out;
  const auto add = [&out](bool ok, std::ostringstream& text) { out.push_back({ok, text.str()}); };
  std::ostringstream failsafe, upright, landing, disarmed, stays;
  failsafe << "estimator outage: last STATE_EST t=" << seconds(e.last_estimate_utime) << " s, lowlevel failsafe "
           << e.failsafe_delay_s << " s later (limit " << limits.max_failsafe_delay_s << " s)";
  add(e.failsafe_delay_s >= 0.0 && e.failsafe_delay_s <= limits.max_failsafe_delay_s, failsafe);
  upright << "estimator outage: max tilt " << e.max_tilt_deg << " deg (limit " << limits.max_tilt_deg << " deg)"
          << (e.crashed ? ", CRASHED" : "");
  add(e.max_tilt_deg < limits.max_tilt_deg && !e.crashed, upright);
  landing << "estimator outage: touchdown at t=" << seconds(e.touchdown_utime) << " s at " << e.touchdown_speed
          << " m/s (limit " << limits.max_touchdown_speed << " m/s)";
  add(e.touchdown_utime >= 0 && e.touchdown_speed < limits.max_touchdown_speed, landing);
  disarmed << "estimator outage: " << (e.disarmed_after_touchdown ? "disarmed" : "NOT disarmed")
           << " on the ground before the restart";
  add(e.disarmed_after_touchdown, disarmed);
  stays << "estimator restart: " << e.rearmed_commands << " MOTOR_CMD armed after the failsafe's disarm (limit 0), "
        << e.resent_takeoffs_after_restart << " TAKEOFF re-sent after the restart (at least 1: else untested)";
  add(e.disarmed_after_touchdown && e.rearmed_commands == 0 && e.resent_takeoffs_after_restart > 0, stays);
  return out;
}

ControllerOutage measureControllerOutage(const logger::FlightLog& log, int64_t kill_wall, int64_t restart_wall,
                                         const Vec3& setpoint, double tolerance, int64_t until_utime) {
  ControllerOutage out;
  const std::ptrdiff_t last = lastReceivedBefore(log.rate_command, kill_wall);
  const std::ptrdiff_t resumed = firstReceivedAtOrAfter(log.rate_command, restart_wall);
  if (last < 0 || resumed < 0) return out;
  out.last_command_utime = log.rate_command[static_cast<size_t>(last)].utime;
  out.resumed_utime = log.rate_command[static_cast<size_t>(resumed)].utime;
  out.failsafe_utime = firstFailsafeAfter(log, out.last_command_utime);
  double lowest = setpoint[2];
  int64_t inside_since = -1;
  bool error_at_resume_set = false;
  for (const SimTruth& truth : log.sim_truth.messages) {
    if (truth.utime < out.last_command_utime || truth.utime > until_utime) continue;
    out.crashed = out.crashed || truth.crashed;
    if (truth.utime <= out.resumed_utime) {
      out.max_gap_tilt_deg = std::max(out.max_gap_tilt_deg, quat::tilt(truth.orientation) * kRadToDeg);
      lowest = std::min(lowest, truth.position[2]);
      continue;
    }
    const double error = (truth.position - setpoint).norm();
    if (!error_at_resume_set) {
      out.error_at_resume = error;
      error_at_resume_set = true;
    }
    if (!(error < tolerance)) {
      inside_since = -1;
    } else if (inside_since < 0) {
      inside_since = truth.utime;
    }
  }
  out.gap_height_loss = setpoint[2] - lowest;
  if (inside_since >= 0) out.return_time_s = seconds(inside_since - out.resumed_utime);
  return out;
}

}  // namespace sdlqr::faults
