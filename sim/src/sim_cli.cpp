#include "sdlqr/sim/sim_cli.hpp"

namespace sdlqr::sim {

SimCommandLine parseSimCommandLine(int argc, const char* const* argv) {
  SimCommandLine o;
  ArgParser parser("sdlqr-sim", "Simulated quadrotor: publishes IMU, VIO_POSE and SIM_TRUTH, takes MOTOR_CMD and\n"
                                "DISTURBANCE, and owns the simulation clock.");
  addProcessOptions(parser, &o.process);
  parser.addOption("--rate", &o.rate, "FACTOR", "simulated seconds per wall second (1 real time, 2 twice as fast)",
                   Range::openClosed(0, 1000));
  parser.addOption("--seed", &o.seed, "N", "noise seed (default: sim.seed of the config)", Range::atLeast(0));
  parser.addOption("--duration", &o.duration, "S", "simulated seconds to run, 0 = until stopped (default 0)",
                   Range::atLeast(0));
  parser.addOption("--scenario", &o.scenario_path, "FILE",
                   "scenario file whose `sim:` key changes the simulated world (plant, wind, start, throw)");
  parser.setEpilog(
      "The vehicle starts landed at sim.initial_position; see the `sim:` section of config/quad255.yaml.\n"
      "Exit codes: 0 stopped (SIGINT/SIGTERM or --duration), 2 bad option or configuration, 1 runtime error.");
  parser.parseOrExit(argc, argv);
  return o;
}

}  // namespace sdlqr::sim
