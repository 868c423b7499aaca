// sdlqr-sim: the plant on the bus. Paces the simulator's core (sim/sim_core.hpp) against the wall
// clock by --rate and binds the bus to its ports (MOTOR_CMD, DISTURBANCE).

#include <cmath>
#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/bus/paced_loop.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/sim/sim_cli.hpp"
#include "sdlqr/sim/sim_core.hpp"

using namespace sdlqr;
using sim::SimCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-sim", [&] {
    const sim::SimCommandLine options = sim::parseSimCommandLine(argc, argv);
    const ConfigReader config = loadVehicleConfig(options.process.config_path);
    sim::SimParams params = sim::SimParams::load(config.child("sim"));
    if (options.seed >= 0) params.seed = options.seed;
    const VehicleParams vehicle = VehicleParams::load(config.child("vehicle"));
    if (options.process.print_config) {
      printProcessConfig(std::cout, "sdlqr-sim", options.process.config_path,
                         {printedSection("vehicle", vehicle), printedSection("sim", params)});
      return 0;
    }
    // The scenario's simulated world (plant mismatch, wind, airborne start, throw), if one is named.
    const sim::SimStress stress =
        options.scenario_path.empty() ? sim::SimStress() : sim::SimStress::loadFromScenario(options.scenario_path);
    SimCore core(vehicle, params, stress);

    bus::Node node("sdlqr-sim", options.process, core.health());
    bus::CoreBinding<SimCore> bus(node, core);  // its ports: SimCore::inputs()
    std::cerr << "sdlqr-sim: " << params.physics_rate_hz << " Hz physics, rate x" << options.rate << ", seed "
              << params.seed << ", channel prefix '" << options.process.vehicle << "'\n";
    node.publishHeartbeat();
    bus::PacingOptions pacing;
    pacing.wall_period = std::chrono::duration<double>(core.simulator().period() / options.rate);
    pacing.max_steps = options.duration > 0.0 ? std::llround(options.duration * params.physics_rate_hz) : -1;
    const int64_t misses = bus::runPaced(node, pacing, [&] {
      if (core.step(bus.outbox())) std::cerr << "sdlqr-sim: " << core.health().lastError() << "\n";
    });
    node.shutdown();
    std::cerr << "sdlqr-sim: stopped at t=" << 1e-6 * static_cast<double>(core.simulator().utime()) << " s after "
              << core.simulator().stepCount() << " steps, " << misses << " deadline misses"
              << (core.simulator().crashed() ? ", crashed" : "") << "\n";
    return 0;
  });
}
