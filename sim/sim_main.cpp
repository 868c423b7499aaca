// sdlqr-sim: the plant on the bus. Paces the simulator's core (sim/sim_core.hpp) against the wall
// clock by --rate and binds MOTOR_CMD and DISTURBANCE to it.

#include <cmath>
#include <iostream>
#include <stdexcept>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/bus/paced_loop.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/sim/sim_core.hpp"

using namespace sdlqr;
using sim::SimCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-sim", [&] {
    ProcessOptions options;
    double rate = 1.0, duration = 0.0;
    long long seed = -1;
    ArgParser parser("sdlqr-sim", "Simulated quadrotor: publishes IMU, VIO_POSE and SIM_TRUTH, takes MOTOR_CMD and\n"
                                  "DISTURBANCE, and owns the simulation clock.");
    addProcessOptions(parser, &options);
    parser.addOption("--rate", &rate, "FACTOR", "simulated seconds per wall second (1 real time, 2 twice as fast)");
    parser.addOption("--seed", &seed, "N", "noise seed, >= 0 (default: sim.seed of the config)");
    parser.addOption("--duration", &duration, "S", "simulated seconds to run, 0 = until stopped (default 0)");
    parser.setEpilog("The vehicle starts landed at sim.initial_position; see the `sim:` section of config/quad255.yaml.\n"
                     "Exit codes: 0 stopped (SIGINT/SIGTERM or --duration), 2 bad option or configuration, 1 runtime error.");
    parser.parseOrExit(argc, argv);
    if (!(rate > 0.0 && rate <= 1000.0)) throw std::invalid_argument("--rate: must be in (0, 1000]");
    if (seed < -1) throw std::invalid_argument("--seed: must be >= 0");
    if (!(duration >= 0.0)) throw std::invalid_argument("--duration: must be >= 0");
    const ConfigReader config = loadVehicleConfig(options.config_path);
    sim::SimParams params = sim::SimParams::load(config.child("sim"));
    if (seed >= 0) params.seed = seed;
    SimCore core(VehicleParams::load(config.child("vehicle")), params);

    bus::Node node("sdlqr-sim", options, core.health());
    bus::CoreBinding<SimCore> bus(node, core);
    bus.bind(&SimCore::onMotorCommand, 1);
    bus.bind(&SimCore::onDisturbance, 16);  // every request matters: they queue, not replace
    std::cerr << "sdlqr-sim: " << params.physics_rate_hz << " Hz physics, rate x" << rate << ", seed " << params.seed
              << ", channel prefix '" << options.vehicle << "'\n";
    node.publishHeartbeat();
    const int64_t misses = bus::runPaced(node, {std::chrono::duration<double>(core.simulator().period() / rate),
                                                duration > 0.0 ? std::llround(duration * params.physics_rate_hz) : -1, 20},
                                         [&] {
                                           if (core.step(bus.outbox())) std::cerr << "sdlqr-sim: " << core.health().lastError() << "\n";
                                         });
    node.shutdown();
    std::cerr << "sdlqr-sim: stopped at t=" << 1e-6 * static_cast<double>(core.simulator().utime()) << " s after "
              << core.simulator().stepCount() << " steps, " << misses << " deadline misses"
              << (core.simulator().crashed() ? ", crashed" : "") << "\n";
    return 0;
  });
}
