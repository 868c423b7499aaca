// sdlqr-top: the terminal alternative to lcm-spy. Once a second: every channel's rate, age and
// size, and the HEARTBEAT of every process (state, CPU, counters, alive or silent).

#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <set>

#include "sdlqr/messages/channels.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/inspect/bus_monitor.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"

namespace {

using namespace sdlqr;

int64_t wallUtime() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<int64_t>(now.tv_sec) * 1'000'000 + now.tv_nsec / 1000;
}

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

// --until-sim-time: returns once a SIM_TRUTH of this vehicle at or past `sim_s` has been heard
// (injected faults are timed on simulation time), or says how far the clock got on timeout. Raw:
// a signed bus's trailer is ignored by the decode, so no key is needed to read the clock.
int waitForSimTime(bus::Node& bus, double sim_s, double timeout_s) {
  const int64_t target = static_cast<int64_t>(sim_s * 1e6 + 0.5);
  int64_t newest = -1;
  bus.subscribeRaw(bus.channel(channel::kSimTruth), [&](const std::string&, const void* data, uint32_t size, int64_t) {
    sim_truth_t truth;
    if (truth.decode(data, 0, static_cast<int>(size)) >= 0) newest = std::max(newest, truth.utime);
  }, 16);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (newest < target && bus.spin(5)) {
    if (std::chrono::steady_clock::now() > deadline) break;
  }
  bus.shutdown();
  if (newest >= target) return 0;
  std::cerr << "sdlqr-top: simulation time " << sim_s << " s not reached within " << timeout_s << " s (newest SIM_TRUTH "
            << 1e-6 * static_cast<double>(newest) << " s)\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-top", [&] {
    ProcessOptions options;
    double duration_s = 0.0;
    double period_s = 1.0;
    bool plain = false;
    std::string wait_for;
    double wait_timeout_s = 10.0;
    double until_sim_s = -1.0;
    ArgParser parser("sdlqr-top",
                     "Terminal view of the bus: once a second each channel's rate, the age of its newest\n"
                     "message and its size, and each process's HEARTBEAT (state, CPU, received, published,\n"
                     "dropped, rejected, errors) with alive / SILENT (no heartbeat for 2.5 s) / stopped.\n"
                     "Listens to every channel (all vehicles); --vehicle only prefixes its own HEARTBEAT.");
    addProcessOptions(parser, &options);
    parser.addOption("--duration", &duration_s, "S", "stop after S seconds of wall time (default: until Ctrl-C)");
    parser.addOption("--period", &period_s, "S", "seconds between reports (default 1)");
    parser.addFlag("--plain", &plain, "never clear the screen (default when stdout is not a terminal)");
    parser.addOption("--wait-for", &wait_for, "P1,P2,...",
                     "only wait until each named process (e.g. sdlqr-estimator) has sent a HEARTBEAT on this\n"
                     "vehicle's channel, then exit 0 (1 after --timeout)");
    parser.addOption("--until-sim-time", &until_sim_s, "T",
                     "only wait until a SIM_TRUTH at or past simulation time T s is heard, then exit 0 (1 after\n"
                     "--timeout): what times an injected fault (scripts/deploy --kill-at, --link-down-at)");
    parser.addOption("--timeout", &wait_timeout_s, "S", "for --wait-for and --until-sim-time, default 10 s of wall time");
    parser.setEpilog("exit codes: 0 stopped by SIGINT/SIGTERM or --duration, 2 bad option");
    parser.parseOrExit(argc, argv);
    if (!(duration_s >= 0.0)) throw std::invalid_argument("--duration: must be >= 0, got " + std::to_string(duration_s));
    if (!(period_s >= 0.1)) throw std::invalid_argument("--period: must be >= 0.1 s, got " + std::to_string(period_s));
    const bool clear = !plain && ::isatty(STDOUT_FILENO);
    if (until_sim_s >= 0.0) {
      if (!(wait_timeout_s > 0.0)) throw std::invalid_argument("--timeout: must be > 0");
      bus::Node bus("sdlqr-top", options);
      return waitForSimTime(bus, until_sim_s, wait_timeout_s);
    }
    if (!wait_for.empty()) {
      if (!(wait_timeout_s > 0.0)) throw std::invalid_argument("--timeout: must be > 0");
      bus::Node bus("sdlqr-top", options);
      return waitForHeartbeats(bus, wait_for, wait_timeout_s);
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
                << inspect::formatReport(monitor.report(wallUtime())) << std::endl;
      if (duration_s > 0.0 && elapsed >= duration_s) break;
    }
    bus.shutdown();
    return 0;
  });
}
