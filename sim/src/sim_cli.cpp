#include "sdlqr/sim/sim_cli.hpp"

#include <stdexcept>

namespace sdlqr::sim {

SimCommandLine parseSimCommandLine(int argc, const char* const* argv) {
  SimCommandLine o;
  ArgParser parser("sdlqr-sim", "Simulated quadrotor: publishes IMU, VIO_POSE and SIM_TRUTH, takes MOTOR_CMD and\n"
                                "DISTURBANCE, and owns the simulation clock.");
  addProcessOptions(parser, &o.process);
  parser.addOption("--rate", &o.rate, "FACTOR", "simulated seconds per wall second (1 real time, 2 twice as fast)");
  parser.addOption("--seed", &o.seed, "N", "noise seed, >= 0 (default: sim.seed of the config)");
  parser.addOption("--duration", &o.duration, "S", "simulated seconds to run, 0 = until stopped (default 0)");
  parser.addOption("--scenario", &o.scenario_path, "FILE",
                   "scenario file whose `sim:` key changes the simulated world (plant, wind, start, throw)");
  parser.setEpilog(
      "The vehicle starts landed at sim.initial_position; see the `sim:` section of config/quad255.yaml.\n"
      "Exit codes: 0 stopped (SIGINT/SIGTERM or --duration), 2 bad option or configuration, 1 runtime error.");
  parser.parseOrExit(argc, argv);
  if (!(o.rate > 0.0 && o.rate <= 1000.0)) throw std::invalid_argument("--rate: must be in (0, 1000]");
  if (o.seed < -1) throw std::invalid_argument("--seed: must be >= 0");
  if (!(o.duration >= 0.0)) throw std::invalid_argument("--duration: must be >= 0");
  return o;
}

}  // namespace sdlqr::sim
