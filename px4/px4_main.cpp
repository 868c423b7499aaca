// sdlqr-px4: binds the bus and a MAVLink link to the PX4 bridge's core (px4/bridge_core.hpp).

#include <chrono>
#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/px4/bench_display.hpp"
#include "sdlqr/px4/bridge_core.hpp"
#include "sdlqr/px4/hover_identification.hpp"
#include "sdlqr/px4/link_binding.hpp"
#include "sdlqr/px4/px4_cli.hpp"

using namespace sdlqr;
using px4::BridgeCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-px4", [&] {
    const px4::BridgeCommandLine options = px4::parseBridgeCommandLine(argc, argv);
    const ConfigReader config = loadVehicleConfig(options.process.config_path);
    const px4::BridgeParams params = px4::BridgeParams::load(config.child("px4"));
    const LqrParams lqr = LqrParams::load(config.child("lqr"));
    const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
    if (options.process.print_config) {
      printProcessConfig(std::cout, "sdlqr-px4", options.process.config_path,
                         {printedSection("px4", params), printedSection("lqr", lqr), printedSection("validation", limits)});
      return 0;
    }
    if (!options.identify_log.empty()) return px4::identifyHover(options.identify_log, params, lqr.gravity, std::cout);
    const auto key = px4::loadLinkKey(options.link);
    const auto io = px4::LinkIo::open(options.link.mavlink_url);
    px4::MavlinkEndpoint endpoint({static_cast<uint8_t>(params.system_id), px4::kOnboardComputerComponent}, *io,
                                  &px4::wallSigningTime, key, static_cast<uint8_t>(options.link.link_id));
    BridgeCore core(params, lqr.gravity, limits, endpoint, {options.bench, options.clock_from_start});
    bus::Node node("sdlqr-px4", options.process, core.health());
    bus::CoreBinding<BridgeCore> bus(node, core);  // its ports: BridgeCore::inputs()
    px4::bindLink(node, *io, endpoint, [&](const uint8_t* data, size_t size, bool datagram) {
      core.onWallTime(bus::monotonicSeconds());
      core.onBytes(data, size, datagram, bus.outbox());
    });
    std::cerr << "sdlqr-px4: MAVLink " << io->describe() << (key ? ", signed" : ", unsigned")
              << (options.bench ? ", BENCH: nothing armed or sent" : "") << "\n";
    px4::BenchDisplay bench(std::cout);
    while (node.spin(core.wallTimePeriodMs())) {
      core.onWallTime(bus::monotonicSeconds());
      if (options.bench) bench.show(core, bus::monotonicSeconds());
    }
    node.shutdown();
    return 0;
  });
}
