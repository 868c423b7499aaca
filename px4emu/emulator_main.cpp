// sdlqr-px4-emulator: paces the emulated PX4's core (px4emu/emulator_core.hpp) against the wall
// clock, binds its MAVLink link and DISTURBANCE on the bus.

#include <cmath>
#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/bus/paced_loop.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/px4/link_binding.hpp"
#include "sdlqr/px4/px4_cli.hpp"
#include "sdlqr/px4emu/emulator_config.hpp"

using namespace sdlqr;
using px4emu::EmulatorCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-px4-emulator", [&] {
    const px4::EmulatorCommandLine options = px4::parseEmulatorCommandLine(argc, argv);
    px4emu::EmulatorConfig config = px4emu::loadEmulatorConfig(loadVehicleConfig(options.process.config_path));
    if (options.seed >= 0) config.sim.seed = options.seed;
    if (options.process.print_config) {
      printProcessConfig(std::cout, "sdlqr-px4-emulator", options.process.config_path, px4emu::printedSections(config));
      return 0;
    }
    const sim::SimStress stress =
        options.scenario_path.empty() ? sim::SimStress() : mission::Scenario::load(options.scenario_path).sim;
    const auto key = px4::loadLinkKey(options.link);
    const auto io = px4::LinkIo::open(options.link.mavlink_url);
    px4::MavlinkEndpoint endpoint({static_cast<uint8_t>(config.emulator.mav_sys_id), px4::kAutopilotComponent}, *io,
                                  &px4::wallSigningTime, key, static_cast<uint8_t>(options.link.link_id));
    EmulatorCore core(config, stress, endpoint);
    bus::Node node("sdlqr-px4-emulator", options.process, core.health());
    bus::CoreBinding<EmulatorCore> bus(node, core);  // its ports: EmulatorCore::inputs()
    px4::bindLink(node, *io, endpoint,
                  [&](const uint8_t* data, size_t size, bool datagram) { core.onBytes(data, size, datagram); });
    std::cerr << "sdlqr-px4-emulator: MAVLink " << io->describe() << (key ? ", signed" : ", unsigned") << ", "
              << config.sim.physics_rate_hz << " Hz physics, rate x" << options.rate << ", seed " << config.sim.seed
              << ", hover throttle " << core.hoverThrottle() << "\n";
    node.publishHeartbeat();
    bus::PacingOptions pacing;
    pacing.wall_period = std::chrono::duration<double>(core.sim().simulator().period() / options.rate);
    const int64_t misses = bus::runPaced(node, pacing, [&] {
      if (core.step(bus.outbox())) std::cerr << "sdlqr-px4-emulator: " << core.health().lastError() << "\n";
    });
    node.shutdown();
    std::cerr << "sdlqr-px4-emulator: stopped at t=" << 1e-6 * static_cast<double>(core.utime()) << " s, " << misses
              << " deadline misses\n";
    return 0;
  });
}
