#pragma once
// Flies a benchmark: every experiment with every controller, and each controller's speed sweep,
// on `jobs` threads, each flight on its own ClosedLoop. Flights share nothing but the loaded
// configuration and land in fixed slots, so the result does not depend on the thread count or
// the order they finished in.

#include <cstdio>
#include <string>
#include <vector>

#include "sdlqr/compare/benchmark.hpp"
#include "sdlqr/compare/experiment_flight.hpp"
#include "sdlqr/compare/sweep.hpp"

namespace sdlqr::compare {

struct CompareOptions {
  int jobs = 1;
  std::FILE* progress = stderr;  // one line per flight landed; nullptr: quiet
};

struct ExperimentInfo {
  std::string name;
  std::string description;
  std::string scenario_path;
  long long seed = 0;
};

struct CompareResult {
  std::string vehicle_path;                 // the vehicle file of the sweep's scenario, else the first experiment's
  std::vector<ExperimentInfo> experiments;  // in the benchmark's order
  std::vector<ExperimentFlight> flights;  // experiment-major, controllers in the benchmark's order
  std::vector<SweepResult> sweeps;        // one per controller, when the benchmark has a sweep
  std::vector<std::string> refusals;      // per sweep speed: empty, or why the path is beyond the vehicle
  ExperimentInfo sweep;                   // the sweep's scenario
  std::vector<double> sweep_limits;       // the scenario's limit of each fail_on criterion
  std::vector<long long> sweep_seeds;     // each speed flies once per seed
  int flown = 0;
  double simulated_s = 0.0;
  double wall_s = 0.0;                    // reported on stderr only: never in the files
};

// Throws ConfigError (a scenario that cannot be flown) or what a flight threw.
CompareResult runCompare(const Benchmark& benchmark, const CompareOptions& options);

}  // namespace sdlqr::compare
