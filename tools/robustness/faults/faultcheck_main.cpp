// sdlqr-faultcheck: what a fault test measured, from its flight log. Prints each process's last
// HEARTBEAT counters that are rejections, watchdogs or injected faults, and fails unless every
// --require'd counter is non-zero in some process, every --forbid'den one zero in all, and every
// process kept its heartbeat to the end
// of the log (liveness.hpp: no gap and no silence at the end longer than --max-silence).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/faults/kernel_loss.hpp"
#include "sdlqr/faults/liveness.hpp"
#include "sdlqr/faults/outage_check.hpp"
#include "sdlqr/logger/flight_log.hpp"

using namespace sdlqr;

namespace {

// "KILL,RESTART": two wall instants in microseconds since the epoch (`date +%s%6N`).
std::pair<int64_t, int64_t> parseOutage(const std::string& option, const std::string& text) {
  long long kill = 0, restart = 0;
  if (std::sscanf(text.c_str(), "%lld,%lld", &kill, &restart) != 2 || kill <= 0 || restart < kill) {
    throw std::invalid_argument(option + ": expected KILL_US,RESTART_US (wall clock, restart >= kill)");
  }
  return {kill, restart};
}

const char* verdict(bool ok) { return ok ? "ok  " : "FAIL"; }

// Prints each finding with its verdict; true when all passed.
bool report(const std::vector<faults::Finding>& findings) {
  for (const faults::Finding& f : findings) std::cout << verdict(f.ok) << " " << f.text << "\n";
  return faults::allOk(findings);
}

std::vector<std::string> splitList(const std::string& text) {
  std::vector<std::string> names;
  size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    if (end > start) names.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  return names;
}

std::string joinList(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ",") + name;
  return text;
}

bool checkGains(const logger::FlightLog& log, const std::string& text, double fallback_timeout, double max_resume) {
  const auto [kill, restart] = parseOutage("--gains-outage", text);
  const faults::GainsOutage g = faults::measureGainsOutage(log, kill, restart, fallback_timeout);
  const double fallback_after = g.first_fallback_utime >= 0 && g.last_gains_utime >= 0
                                    ? 1e-6 * static_cast<double>(g.first_fallback_utime - g.last_gains_utime)
                                    : -1.0;
  const bool fallback_ok = g.fallback_commands > 0 && g.late_non_fallback_commands == 0;
  const bool resume_ok = g.resume_after_up_s <= max_resume && g.fresh_commands_after_resume > 0;  // false on NaN
  std::cout << verdict(fallback_ok) << " gains outage: hover K in use " << fallback_after
            << " s after the last GAINS (timeout " << fallback_timeout << " s), " << g.fallback_commands
            << " RATE_CMD on it, " << g.late_non_fallback_commands << " past the timeout on another K\n";
  std::cout << verdict(resume_ok) << " gains restart: first GAINS " << g.resume_after_up_s
            << " s of simulation time after the restarted solver's first HEARTBEAT (limit " << max_resume << " s; "
            << g.resume_delay_s << " s of wall time after the restart), then " << g.fresh_commands_after_resume
            << " RATE_CMD on fresh GAINS\n";
  return fallback_ok && resume_ok;
}

bool checkEstimator(const logger::FlightLog& log, const std::string& text, const faults::EstimatorLimits& limits) {
  const auto [kill, restart] = parseOutage("--estimator-outage", text);
  return report(faults::judgeEstimatorOutage(faults::measureEstimatorOutage(log, kill, restart), limits));
}

bool checkController(const logger::FlightLog& log, const std::string& text, const std::string& setpoint_text,
                     double until, double tolerance, double max_return, double max_gap_tilt) {
  const auto [kill, restart] = parseOutage("--controller-outage", text);
  double v[3] = {};
  if (std::sscanf(setpoint_text.c_str(), "%lf,%lf,%lf", &v[0], &v[1], &v[2]) != 3) {
    throw std::invalid_argument("--setpoint: expected X,Y,Z");
  }
  const faults::ControllerOutage c = faults::measureControllerOutage(
      log, kill, restart, Vec3(v[0], v[1], v[2]), tolerance, static_cast<int64_t>(until * 1e6));
  const double failsafe_delay =
      c.failsafe_utime >= 0 ? 1e-6 * static_cast<double>(c.failsafe_utime - c.last_command_utime) : -1.0;
  const bool gap_ok = c.failsafe_utime >= 0 && c.failsafe_utime <= c.resumed_utime && c.max_gap_tilt_deg < max_gap_tilt &&
                      !c.crashed;
  const bool return_ok = c.resumed_utime >= 0 && c.return_time_s >= 0.0 && c.return_time_s <= max_return;
  std::cout << verdict(gap_ok) << " controller outage: last RATE_CMD t=" << 1e-6 * c.last_command_utime
            << " s, lowlevel failsafe " << failsafe_delay << " s later, RATE_CMD again at t="
            << 1e-6 * c.resumed_utime << " s; in the gap max tilt " << c.max_gap_tilt_deg << " deg (limit "
            << max_gap_tilt << " deg), height lost " << c.gap_height_loss << " m" << (c.crashed ? ", CRASHED" : "")
            << "\n";
  std::cout << verdict(return_ok) << " controller restart: " << c.error_at_resume << " m from the setpoint on resuming, within "
            << tolerance << " m for good " << c.return_time_s << " s later (limit " << max_return
            << " s, held until t=" << until << " s)\n";
  return gap_ok && return_ok;
}

// Every option of the command line, with its default.
struct Options {
  std::string required_text, forbidden_text, vehicle;
  double max_silence = 2.5;
  bool require_complete = false;
  std::string hover_text;
  double max_hover_error = 0.1;
  std::string expected_text, may_stop_text = joinList(faults::kProcessesThatMayStop), also_may_stop_text;
  long long kernel_dropped = -1;
  std::string gains_outage, estimator_outage, controller_outage, setpoint_text;
  double fallback_timeout = 1.0, max_gains_resume = 0.25;
  double max_failsafe_delay = 0.2, max_tilt = 30.0, max_touchdown_speed = 1.0;
  double settle_until = 0.0, return_tolerance = 0.1, max_return = 3.0, max_gap_tilt = 10.0;
  std::vector<std::string> positional;
};

// What every fault test may ask: counters, liveness, a hover and the kernel's drops.
void addCounterOptions(ArgParser& parser, Options& o) {
  parser.addOption("--require", &o.required_text, "A,B,...", "counters that must be > 0 in some process");
  parser.addOption("--forbid", &o.forbidden_text, "A,B,...", "counters that must stay 0 in every process");
  parser.addOption("--max-silence", &o.max_silence, "S",
                   "longest heartbeat gap of any process, and longest silence before the end of the log,\n"
                   "wall time (default 2.5)", Range::above(0));
  parser.addOption("--expect", &o.expected_text, "A,B,...", "processes that must have sent heartbeats");
  parser.addOption("--may-stop", &o.may_stop_text, "A,B,...",
                   "processes that may end before the log does, with a STOPPING heartbeat\n"
                   "(default " + o.may_stop_text + ")");
  parser.addOption("--also-may-stop", &o.also_may_stop_text, "A,B,...",
                   "processes added to --may-stop's list (a test's own publisher, say)");
  parser.addOption("--hover", &o.hover_text, "T0,T1,X,Y,Z",
                   "max |truth - (X,Y,Z)| over simulation time [T0, T1] s must stay below --max-hover-error");
  parser.addOption("--max-hover-error", &o.max_hover_error, "M", "default 0.1 m", Range::above(0));
  parser.addFlag("--complete", &o.require_complete, "fail unless the log ends in a whole event");
  parser.addOption("--vehicle", &o.vehicle, "PREFIX", "channel prefix of the vehicle");
  parser.addOption("--kernel-drops", &o.kernel_dropped, "N",
                   "the datagrams a loss rule dropped in the kernel (scripts/packet_loss --dropped): must be > 0,\n"
                   "match the log's gaps, and every subscriber must have counted them (kernel_loss.hpp)");
}

// A process killed and restarted by the test, and what its outage must look like.
void addOutageOptions(ArgParser& parser, Options& o) {
  parser.addOption("--gains-outage", &o.gains_outage, "KILL_US,RESTART_US",
                   "sdlqr-gains killed/restarted at these wall instants (date +%s%6N): the hover K takes over\n"
                   "after --fallback-timeout and fresh GAINS return within --max-gains-resume");
  parser.addOption("--fallback-timeout", &o.fallback_timeout, "S", "controller.gains_fallback_s (default 1.0)",
                   Range::above(0));
  parser.addOption("--max-gains-resume", &o.max_gains_resume, "S",
                   "first GAINS after the restarted solver is up, default 0.25 s of simulation time\n"
                   "(two 10 Hz solve periods and an estimate)", Range::above(0));
  parser.addOption("--estimator-outage", &o.estimator_outage, "KILL_US,RESTART_US",
                   "sdlqr-estimator killed/restarted: the lowlevel failsafe engages within --max-failsafe-delay,\n"
                   "tilt stays below --max-tilt, touchdown slower than --max-touchdown-speed, disarmed on the\n"
                   "ground, and never armed again to the end of the log (the mission re-sends its TAKEOFF)");
  parser.addOption("--max-failsafe-delay", &o.max_failsafe_delay, "S", "default 0.2 s of simulation time",
                   Range::above(0));
  parser.addOption("--max-tilt", &o.max_tilt, "DEG", "default 30", Range::openClosed(0, 90));
  parser.addOption("--max-touchdown-speed", &o.max_touchdown_speed, "M_S", "default 1.0", Range::above(0));
  parser.addOption("--controller-outage", &o.controller_outage, "KILL_US,RESTART_US",
                   "sdlqr-controller killed/restarted: the failsafe holds the vehicle level (tilt below\n"
                   "--max-gap-tilt) and after the restart it is back within --return-tolerance of --setpoint\n"
                   "within --max-return-time, staying there until --settle-until");
  parser.addOption("--setpoint", &o.setpoint_text, "X,Y,Z", "held setpoint of --controller-outage [m]");
  parser.addOption("--settle-until", &o.settle_until, "T", "simulation time [s] the return must last until");
  parser.addOption("--return-tolerance", &o.return_tolerance, "M", "default 0.1 m", Range::above(0));
  parser.addOption("--max-return-time", &o.max_return, "S", "default 3 s of simulation time", Range::above(0));
  parser.addOption("--max-gap-tilt", &o.max_gap_tilt, "DEG", "default 10: level while the controller is away",
                   Range::openClosed(0, 90));
}

void parseOptions(int argc, char** argv, Options& o) {
  ArgParser parser("sdlqr-faultcheck",
                   "Reads a flight log and prints the rejection, watchdog and fault counters of every process.");
  addCounterOptions(parser, o);
  addOutageOptions(parser, o);
  parser.setEpilog("exit codes: 0 every check passed, 1 a check failed, 2 bad option or unreadable log");
  parser.allowPositional(&o.positional, "LOG");
  parser.parseOrExit(argc, argv);
  if (o.positional.size() != 1) throw std::invalid_argument("expected one LOG file");
  // Bad outage options fail before the log is read.
  if (!o.gains_outage.empty()) parseOutage("--gains-outage", o.gains_outage);
  if (!o.estimator_outage.empty()) parseOutage("--estimator-outage", o.estimator_outage);
  if (!o.controller_outage.empty()) parseOutage("--controller-outage", o.controller_outage);
  if (!o.controller_outage.empty() && o.setpoint_text.empty()) {
    throw std::invalid_argument("--controller-outage needs --setpoint");
  }
}

// Each process's own last heartbeat: a forged one (the fuzz flight's) could report any counter.
std::map<std::string, const logger::HeartbeatRecord*> lastHeartbeats(const logger::FlightLog& log,
                                                                     const faults::Liveness& alive) {
  std::map<std::string, const logger::HeartbeatRecord*> last;
  for (const faults::ProcessLiveness& p : alive.processes) {
    if (p.last_index >= 0) last[p.process] = &log.heartbeat[static_cast<size_t>(p.last_index)];
  }
  return last;
}

void printLogFile(const logger::FlightLog& log) {
  std::cout << "log: " << log.file.events << " events, " << log.file.file_bytes << " bytes, "
            << (log.file.complete() ? "complete" : "INCOMPLETE") << " (truncated tail " << log.file.truncated_tail_bytes
            << " bytes, skipped " << log.file.skipped_bytes << " bytes)\n";
}

// Prints each process's counts and its non-zero fault counters; returns each counter summed over
// the processes.
std::map<std::string, int64_t> printCounters(const std::map<std::string, const logger::HeartbeatRecord*>& last) {
  std::map<std::string, int64_t> totals;
  for (const auto& [process, hb] : last) {
    std::cout << process << ": rejected " << hb->rejected << ", dropped " << hb->dropped << ", errors " << hb->errors
              << ", last heartbeat " << logger::processStateName(hb->state) << "\n";
    for (const auto& [name, value] : hb->counters) {
      totals[name] += value;
      const bool interesting = name.rfind("reject.", 0) == 0 || name.rfind("watchdog.", 0) == 0 ||
                               name.rfind("fault.", 0) == 0 || name.rfind("fuzz.", 0) == 0 ||
                               name.rfind("failsafe.", 0) == 0 || name.rfind("mavlink.drop.", 0) == 0;
      if (interesting && value != 0) std::cout << "    " << name << " " << value << "\n";
    }
  }
  return totals;
}

faults::LivenessRules livenessRules(const Options& o) {
  faults::LivenessRules liveness;
  liveness.max_silence_s = o.max_silence;
  liveness.expected = splitList(o.expected_text);
  liveness.may_stop = splitList(o.may_stop_text);
  for (const std::string& process : splitList(o.also_may_stop_text)) liveness.may_stop.push_back(process);
  // A process killed on purpose is silent for its outage; restarted, it must beat to the end.
  if (!o.gains_outage.empty()) liveness.killed.push_back("sdlqr-gains");
  if (!o.estimator_outage.empty()) liveness.killed.push_back("sdlqr-estimator");
  if (!o.controller_outage.empty()) liveness.killed.push_back("sdlqr-controller");
  return liveness;
}

// --hover: the truth's distance to the setpoint over a time window; a crash anywhere fails it.
bool checkHover(const logger::FlightLog& log, const std::string& hover_text, double max_hover_error) {
  double v[5] = {};
  if (std::sscanf(hover_text.c_str(), "%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4]) != 5) {
    throw std::invalid_argument("--hover: expected T0,T1,X,Y,Z");
  }
  const Vec3 setpoint(v[2], v[3], v[4]);
  double worst = 0.0, sum_sq = 0.0;
  int64_t samples = 0;
  bool crashed = false;
  for (const SimTruth& truth : log.sim_truth.messages) {
    const double t = 1e-6 * static_cast<double>(truth.utime);
    crashed = crashed || truth.crashed;
    if (t < v[0] || t > v[1]) continue;
    const double error = (truth.position - setpoint).norm();
    worst = std::max(worst, std::isfinite(error) ? error : 1e9);
    sum_sq += error * error;
    ++samples;
  }
  const double rms = samples > 0 ? std::sqrt(sum_sq / static_cast<double>(samples)) : 0.0;
  const bool hover_ok = samples > 0 && worst < max_hover_error && !crashed;
  std::cout << verdict(hover_ok) << " hover error over t=[" << v[0] << ", " << v[1] << "] s (" << samples
            << " truth samples): max " << worst << " m, RMS " << rms << " m (limit " << max_hover_error << " m)"
            << (crashed ? ", CRASHED" : "") << "\n";
  return hover_ok;
}

// --require'd counters non-zero in some process, --forbid'den ones zero in all; prints each.
bool checkCounters(const std::map<std::string, int64_t>& totals, const Options& o) {
  const auto total = [&](const std::string& name) {
    const auto it = totals.find(name);
    return it == totals.end() ? int64_t{0} : it->second;
  };
  bool ok = true;
  for (const std::string& name : splitList(o.required_text)) {
    std::cout << (total(name) > 0 ? "ok   " : "FAIL ") << name << " = " << total(name) << " over all processes\n";
    ok = ok && total(name) > 0;
  }
  for (const std::string& name : splitList(o.forbidden_text)) {
    std::cout << (total(name) == 0 ? "ok   " : "FAIL ") << name << " = " << total(name)
              << " over all processes (must stay 0)\n";
    ok = ok && total(name) == 0;
  }
  return ok;
}

// The outages the test caused, each judged (every one runs and prints, whatever the others gave).
bool checkOutages(const logger::FlightLog& log, const Options& o) {
  bool ok = true;
  if (!o.gains_outage.empty()) ok = checkGains(log, o.gains_outage, o.fallback_timeout, o.max_gains_resume) && ok;
  if (!o.estimator_outage.empty()) {
    ok = checkEstimator(log, o.estimator_outage, {o.max_failsafe_delay, o.max_tilt, o.max_touchdown_speed}) && ok;
  }
  if (!o.controller_outage.empty()) {
    ok = checkController(log, o.controller_outage, o.setpoint_text, o.settle_until, o.return_tolerance, o.max_return,
                         o.max_gap_tilt) && ok;
  }
  return ok;
}

int run(const Options& o) {
  const logger::FlightLog log = logger::FlightLog::load(o.positional[0], o.vehicle);
  const faults::Liveness alive = faults::measureLiveness(log);
  const auto last = lastHeartbeats(log, alive);
  bool ok = true;
  printLogFile(log);
  if (o.require_complete && !log.file.complete()) ok = false;
  const std::map<std::string, int64_t> totals = printCounters(last);
  if (alive.longest_machine_stall_s > 0.0) {
    std::cout << "bus: the whole machine stalled, " << alive.longest_machine_stall_s << " s at most without any "
              << "datagram (over " << faults::kMachineStallS << " s: not counted in any process's heartbeat gaps)\n";
  }
  ok = report(faults::judgeLiveness(alive, livenessRules(o))) && ok;
  if (!o.hover_text.empty()) ok = checkHover(log, o.hover_text, o.max_hover_error) && ok;
  if (o.kernel_dropped >= 0) ok = report(faults::judgeKernelLoss(log, alive, o.kernel_dropped)) && ok;
  ok = checkCounters(totals, o) && ok;
  ok = checkOutages(log, o) && ok;
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-faultcheck", [&] {
    Options options;
    parseOptions(argc, argv, options);
    return run(options);
  });
}
