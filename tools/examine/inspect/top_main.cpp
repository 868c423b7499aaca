// sdlqr-top: the terminal alternative to lcm-spy. Once a second: every channel's rate, age and
// size, and the HEARTBEAT of every process (state, CPU, counters, alive or silent).

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <set>
#include <utility>
#include <vector>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/inspect/bus_monitor.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/wall_clock.hpp"

namespace {

using namespace sdlqr;

bool isHeartbeat(const std::string& channel) {
  const std::string_view base = channel::kHeartbeat;
  return channel.size() >= base.size() && channel.compare(channel.size() - base.size(), base.size(), base) == 0 &&
         (channel.size() == base.size() || channel[channel.size() - base.size() - 1] == '/');
}

// --wait-for: returns once every named process has published a HEARTBEAT on this vehicle's
// channel (the launcher starts the simulator only then), or names the missing ones on timeout.
int waitForHeartbeats(bus::Node& bus, const std::string& names, double timeout_s) {
  std::set<std::string> missing;
  for (size_t start = 0; start <= names.size();) {
    const size_t comma = std::min(names.find(',', start), names.size());
    if (comma > start) missing.insert(names.substr(start, comma - start));
    start = comma + 1;
  }
  if (missing.empty()) throw std::invalid_argument("--wait-for: expected process names separated by commas");
  const std::string channel = bus.channel(channel::kHeartbeat);
  bus.subscribe<heartbeat_t>(channel::kHeartbeat, [&](const heartbeat_t& hb) { missing.erase(hb.process); }, 256);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!missing.empty() && bus.spin(20)) {
    if (std::chrono::steady_clock::now() > deadline) break;
  }
  // A waiter that took over a second has beaten (STARTING): its last heartbeat says it stopped.
  bus.shutdown();
  if (missing.empty()) return 0;
  std::string text;
  for (const std::string& name : missing) text += (text.empty() ? "" : ", ") + name;
  std::cerr << "sdlqr-top: no HEARTBEAT on " << channel << " within " << timeout_s << " s from: " << text << "\n";
  return 1;
}

// --at-sim-time: prints "sim time S" (S as given) as soon as the simulation clock (SIM_CLOCK or
// SIM_TRUTH of this vehicle) reaches each mark, then exits 0; 1 when the clock has not reached them
// after timeout_s of wall time. A test injects its faults at these lines, on the flight's own time:
// a machine that stalls for seconds stalls the simulation with it, so a fault never lands late.
int printSimTimeMarks(bus::Node& bus, const std::string& list, double timeout_s) {
  std::vector<std::pair<double, std::string>> marks;  // seconds, as written
  for (size_t start = 0; start < list.size();) {
    const size_t comma = std::min(list.find(',', start), list.size());
    const std::string text = list.substr(start, comma - start);
    size_t used = 0;
    double mark = std::nan("");
    try {
      mark = std::stod(text, &used);
    } catch (const std::exception&) {
    }
    if (used != text.size() || !(mark >= 0.0) || (!marks.empty() && mark <= marks.back().first)) {
      throw std::invalid_argument("--at-sim-time: expected increasing seconds separated by commas, got '" + list + "'");
    }
    marks.emplace_back(mark, text);
    start = comma + 1;
  }
  if (marks.empty()) throw std::invalid_argument("--at-sim-time: expected seconds separated by commas");
  size_t next = 0;
  const auto reached = [&](int64_t sim_us) {
    for (; next < marks.size() && static_cast<double>(sim_us) >= marks[next].first * 1e6; ++next) {
      std::cout << "sim time " << marks[next].second << std::endl;
    }
  };
  bus.subscribe<sim_clock_t>(channel::kSimClock, [&](const sim_clock_t& clock) { reached(clock.utime); }, 16);
  // The simulator's truth carries the same time: on an emulated autopilot's host (sdlqr-px4-emulator)
  // it is the clock heard there, the vehicle's SIM_CLOCK coming from the bridge across the link.
  bus.subscribe<sim_truth_t>(channel::kSimTruth, [&](const sim_truth_t& truth) { reached(truth.utime); }, 16);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (next < marks.size() && bus.spin(20) && std::chrono::steady_clock::now() <= deadline) {
  }
  bus.shutdown();
  if (next == marks.size()) return 0;
  std::cerr << "sdlqr-top: the simulation clock on " << bus.channel(channel::kSimClock) << " did not reach "
            << marks[next].second << " s within " << timeout_s << " s\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-top", [&] {
    ProcessOptions options;
    double duration_s = 0.0;
    double period_s = 1.0;
    bool plain = false;
    std::string wait_for, sim_time_marks;
    double wait_timeout_s = -1.0;
    ArgParser parser("sdlqr-top",
                     "Terminal view of the bus: once a second each channel's rate, the age of its newest\n"
                     "message and its size, and each process's HEARTBEAT (state, CPU, received, published,\n"
                     "dropped, rejected, errors) with alive / SILENT (no heartbeat for 2.5 s) / stopped.\n"
                     "Listens to every channel (all vehicles); --vehicle only prefixes its own HEARTBEAT.");
    addProcessOptions(parser, &options);
    parser.addOption("--duration", &duration_s, "S", "stop after S seconds of wall time (default: until Ctrl-C)",
                     Range::atLeast(0));
    parser.addOption("--period", &period_s, "S", "seconds between reports (default 1)", Range::atLeast(0.1));
    parser.addFlag("--plain", &plain, "never clear the screen (default when stdout is not a terminal)");
    parser.addOption("--wait-for", &wait_for, "P1,P2,...",
                     "only wait until each named process (e.g. sdlqr-estimator) has sent a HEARTBEAT on this\n"
                     "vehicle's channel, then exit 0 (1 after --timeout)");
    parser.addOption("--at-sim-time", &sim_time_marks, "S1,S2,...",
                     "only print 'sim time S' as the simulation clock (SIM_CLOCK, SIM_TRUTH) reaches each S seconds,\n"
                     "then exit 0 (1 after --timeout): fault injections timed on the flight's own clock");
    parser.addOption("--timeout", &wait_timeout_s, "S",
                     "wall seconds for --wait-for (default 10) or --at-sim-time (default 120)", Range::above(0));
    parser.setEpilog(
        "exit codes: 0 stopped by SIGINT/SIGTERM or --duration, or the wait is over; 1 --wait-for or --at-sim-time\n"
        "timed out; 2 bad option");
    parser.parseOrExit(argc, argv);
    const bool clear = !plain && ::isatty(STDOUT_FILENO);
    if (wait_timeout_s < 0.0) wait_timeout_s = sim_time_marks.empty() ? 10.0 : 120.0;
    if (!wait_for.empty() && !sim_time_marks.empty()) {
      throw std::invalid_argument("--wait-for and --at-sim-time: one at a time");
    }
    if (!wait_for.empty()) {
      bus::Node bus("sdlqr-top", options);
      return waitForHeartbeats(bus, wait_for, wait_timeout_s);
    }
    if (!sim_time_marks.empty()) {
      bus::Node bus("sdlqr-top", options);
      return printSimTimeMarks(bus, sim_time_marks, wait_timeout_s);
    }

    inspect::BusMonitor monitor;
    bus::Node bus("sdlqr-top", options);
    bus.subscribeRaw(".*", [&](const std::string& channel, const void* data, uint32_t size, int64_t receive_utime) {
      monitor.onMessage(channel, size, receive_utime);
      if (!isHeartbeat(channel)) return;
      heartbeat_t heartbeat;
      if (heartbeat.decode(data, 0, static_cast<int>(size)) < 0) return;
      monitor.onHeartbeat(channel, bus::fromLcm(heartbeat), receive_utime);
    }, 4096);
    bus.setState(bus::ProcessState::kRunning);

    const auto start = std::chrono::steady_clock::now();
    auto next_report = start + std::chrono::duration<double>(period_s);
    while (bus.spin(20)) {
      const auto now = std::chrono::steady_clock::now();
      if (now < next_report) continue;
      next_report += std::chrono::duration<double>(period_s);
      const double elapsed = std::chrono::duration<double>(now - start).count();
      if (clear) std::cout << "\033[H\033[2J";
      std::cout << "sdlqr-top  t=" << static_cast<int>(elapsed) << " s\n"
                << inspect::formatReport(monitor.report(bus::realtimeUtime())) << std::endl;
      if (duration_s > 0.0 && elapsed >= duration_s) break;
    }
    bus.shutdown();
    return 0;
  });
}
