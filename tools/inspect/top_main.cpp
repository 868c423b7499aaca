// sdlqr-top: the terminal alternative to lcm-spy. Once a second: every channel's rate, age and
// size, and the HEARTBEAT of every process (state, CPU, counters, alive or silent).

#include <time.h>
#include <unistd.h>

#include <chrono>
#include <iostream>

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

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-top", [&] {
    ProcessOptions options;
    double duration_s = 0.0;
    double period_s = 1.0;
    bool plain = false;
    ArgParser parser("sdlqr-top",
                     "Terminal view of the bus: once a second each channel's rate, the age of its newest\n"
                     "message and its size, and each process's HEARTBEAT (state, CPU, received, published,\n"
                     "dropped, rejected, errors) with alive / SILENT (no heartbeat for 2.5 s) / stopped.\n"
                     "Listens to every channel (all vehicles); --vehicle only prefixes its own HEARTBEAT.");
    addProcessOptions(parser, &options);
    parser.addOption("--duration", &duration_s, "S", "stop after S seconds of wall time (default: until Ctrl-C)");
    parser.addOption("--period", &period_s, "S", "seconds between reports (default 1)");
    parser.addFlag("--plain", &plain, "never clear the screen (default when stdout is not a terminal)");
    parser.setEpilog("exit codes: 0 stopped by SIGINT/SIGTERM or --duration, 2 bad option");
    parser.parseOrExit(argc, argv);
    if (!(duration_s >= 0.0)) throw std::invalid_argument("--duration: must be >= 0, got " + std::to_string(duration_s));
    if (!(period_s >= 0.1)) throw std::invalid_argument("--period: must be >= 0.1 s, got " + std::to_string(period_s));
    const bool clear = !plain && ::isatty(STDOUT_FILENO);

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
