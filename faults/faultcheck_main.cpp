// sdlqr-faultcheck: what a fault test measured, from its flight log. Prints each process's last
// HEARTBEAT counters that are rejections, watchdogs or injected faults, and fails unless every
// --require'd counter is non-zero in some process and every process kept its heartbeat to the end.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "sdlqr/common/cli.hpp"
#include "sdlqr/logger/flight_log.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  return runMain("sdlqr-faultcheck", [&] {
    std::string required_text, vehicle;
    double max_silence = 2.5;
    bool require_complete = false;
    std::string hover_text;
    double max_hover_error = 0.1;
    ArgParser parser("sdlqr-faultcheck",
                     "Reads a flight log and prints the rejection, watchdog and fault counters of every process.");
    parser.addOption("--require", &required_text, "A,B,...", "counters that must be > 0 in some process");
    parser.addOption("--max-silence", &max_silence, "S", "longest heartbeat gap of any process, wall time (default 2.5)");
    parser.addOption("--hover", &hover_text, "T0,T1,X,Y,Z",
                     "max |truth - (X,Y,Z)| over simulation time [T0, T1] s must stay below --max-hover-error");
    parser.addOption("--max-hover-error", &max_hover_error, "M", "default 0.1 m");
    parser.addFlag("--complete", &require_complete, "fail unless the log ends in a whole event");
    parser.addOption("--vehicle", &vehicle, "PREFIX", "channel prefix of the vehicle");
    parser.setEpilog("exit codes: 0 every check passed, 1 a check failed, 2 bad option or unreadable log");
    std::vector<std::string> positional;
    parser.allowPositional(&positional, "LOG");
    parser.parseOrExit(argc, argv);
    if (positional.size() != 1) throw std::invalid_argument("expected one LOG file");
    const logger::FlightLog log = logger::FlightLog::load(positional[0], vehicle);

    std::map<std::string, const logger::HeartbeatRecord*> last;
    std::map<std::string, std::pair<int64_t, int64_t>> first_last_receive;  // wall us
    std::map<std::string, double> longest_gap_s;
    for (size_t i = 0; i < log.heartbeat.size(); ++i) {
      const logger::HeartbeatRecord& hb = log.heartbeat[i];
      const int64_t t = log.heartbeat.receive_utime[i];
      auto [it, inserted] = first_last_receive.try_emplace(hb.process, t, t);
      if (!inserted) {
        longest_gap_s[hb.process] = std::max(longest_gap_s[hb.process], 1e-6 * static_cast<double>(t - it->second.second));
        it->second.second = t;
      }
      last[hb.process] = &hb;
    }
    int64_t log_end = 0;
    for (const auto& [process, times] : first_last_receive) log_end = std::max(log_end, times.second);

    bool ok = true;
    std::cout << "log: " << log.file.events << " events, " << log.file.file_bytes << " bytes, "
              << (log.file.complete() ? "complete" : "INCOMPLETE") << " (truncated tail " << log.file.truncated_tail_bytes
              << " bytes, skipped " << log.file.skipped_bytes << " bytes)\n";
    if (require_complete && !log.file.complete()) ok = false;
    std::map<std::string, int64_t> totals;
    for (const auto& [process, hb] : last) {
      std::cout << process << ": rejected " << hb->rejected << ", dropped " << hb->dropped << ", errors " << hb->errors
                << ", last heartbeat " << logger::processStateName(hb->state) << ", longest heartbeat gap "
                << longest_gap_s[process] << " s\n";
      for (const auto& [name, value] : hb->counters) {
        totals[name] += value;
        const bool interesting = name.rfind("reject.", 0) == 0 || name.rfind("watchdog.", 0) == 0 ||
                                 name.rfind("fault.", 0) == 0 || name.rfind("fuzz.", 0) == 0;
        if (interesting && value != 0) std::cout << "    " << name << " " << value << "\n";
      }
      if (process != "sdlqr-fuzz-publisher" && longest_gap_s[process] > max_silence) {
        std::cout << "FAIL " << process << ": heartbeat silent for " << longest_gap_s[process] << " s (stalled?)\n";
        ok = false;
      }
    }
    if (!hover_text.empty()) {
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
      std::cout << "hover error over t=[" << v[0] << ", " << v[1] << "] s (" << samples << " truth samples): max "
                << worst << " m, RMS " << rms << " m (limit " << max_hover_error << " m)"
                << (crashed ? ", CRASHED" : "") << "\n";
      ok = ok && samples > 0 && worst < max_hover_error && !crashed;
    }
    size_t start = 0;
    while (start <= required_text.size() && !required_text.empty()) {
      size_t end = required_text.find(',', start);
      if (end == std::string::npos) end = required_text.size();
      const std::string name = required_text.substr(start, end - start);
      start = end + 1;
      if (name.empty()) continue;
      const int64_t total = totals.count(name) ? totals[name] : 0;
      std::cout << (total > 0 ? "ok   " : "FAIL ") << name << " = " << total << " over all processes\n";
      ok = ok && total > 0;
    }
    return ok ? 0 : 1;
  });
}
