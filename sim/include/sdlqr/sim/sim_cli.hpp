#pragma once
// The command line of sdlqr-sim, kept out of main so that main only binds and paces the bus.

#include <string>

#include "sdlqr/config/cli.hpp"

namespace sdlqr::sim {

struct SimCommandLine {
  ProcessOptions process;
  double rate = 1.0;      // [-] simulated seconds per wall second
  long long seed = -1;    // -1: sim.seed of the config
  double duration = 0.0;  // [s] of simulation time, 0: until stopped
  std::string scenario_path;  // its `sim:` key: plant mismatch, wind, airborne start, throw
};

// Exits on --help or a bad option (as ArgParser); throws std::invalid_argument naming the option
// when a value is out of range.
SimCommandLine parseSimCommandLine(int argc, const char* const* argv);

}  // namespace sdlqr::sim
