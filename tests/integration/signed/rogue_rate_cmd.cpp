// A process on the bus without the bus key (tests/integration/signed): it listens to the flight
// (a Node without a key still decodes signed messages), waits for simulation time --at, then for
// --for wall seconds publishes RATE_CMD at --rate Hz that the bodyrate loop would take: finite,
// in range (no rotation, --thrust within [0, max]), stamped with the newest IMU time heard (newer
// than the controller's, which follow the estimate). Unsigned, since it has no key. With thrust
// 0 the vehicle drops if the loop takes them; exit 0 once they are sent.
//   rogue_rate_cmd [--at S] [--for S] [--rate HZ] [--thrust M_S2] [--lcm-url URL]

#include <chrono>
#include <cstdint>
#include <iostream>
#include <stdexcept>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/config/cli.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  return runMain("rogue_rate_cmd", [&] {
    ProcessOptions options;
    double at_s = 6.0, for_s = 1.5, rate_hz = 500.0, thrust = 0.0;
    ArgParser parser("rogue_rate_cmd", "Publishes well-formed, in-range, newer RATE_CMD mid-flight, unsigned.");
    parser.addOption("--at", &at_s, "S", "simulation time to start at (default 6)");
    parser.addOption("--for", &for_s, "S", "wall seconds to send for (default 1.5)");
    parser.addOption("--rate", &rate_hz, "HZ", "commands per second (default 500)");
    parser.addOption("--thrust", &thrust, "M_S2", "mass-normalized collective thrust of every command (default 0)");
    parser.addOption("--lcm-url", &options.lcm_url, "URL", "LCM provider");
    parser.parseOrExit(argc, argv);
    if (!(rate_hz > 0.0 && rate_hz <= 5000.0)) throw std::invalid_argument("--rate: expected (0, 5000] Hz");

    bus::Node node("rogue-rate-cmd", options);
    int64_t imu_utime = -1;
    node.subscribe<imu_t>(channel::kImu, [&](const imu_t& m) { imu_utime = m.utime; });
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (node.spin(5) && imu_utime < static_cast<int64_t>(at_s * 1e6)) {
      if (std::chrono::steady_clock::now() > give_up) {
        std::cout << "rogue: no flight heard\n";
        return 1;
      }
    }
    const auto period = std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(1.0 / rate_hz));
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(for_s));
    auto next = std::chrono::steady_clock::now();
    RateCommand command;
    command.thrust = thrust;
    int64_t sent = 0;
    const int64_t first_utime = imu_utime;
    while (node.running() && std::chrono::steady_clock::now() < end) {
      command.utime = imu_utime;
      command.seq = 1'000'000 + sent;
      node.publish(channel::kRateCommand, bus::toLcm(command));
      ++sent;
      next += period;
      while (std::chrono::steady_clock::now() < next && node.waitReadable(next - std::chrono::steady_clock::now())) {
        node.spin(0);  // the newest IMU time
      }
    }
    std::cout << "rogue: sent " << sent << " RATE_CMD over simulation time t=[" << 1e-6 * static_cast<double>(first_utime)
              << ", " << 1e-6 * static_cast<double>(imu_utime) << "] s, thrust " << thrust << " m/s^2, unsigned\n";
    node.shutdown();
    return sent > 0 ? 0 : 1;
  });
}
