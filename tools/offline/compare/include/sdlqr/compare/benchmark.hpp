#pragma once
// A benchmark file (`./sdlqr compare`, config/compare/benchmark.yaml): the controllers compared,
// the experiments each flies, and a speed sweep of one closed path:
//
//   controllers: [sdlqr, hover_lqr, geometric]   # laws of the controller process (lqr.law)
//   experiments: [hover_jumps, throw]             # names in config/scenarios/, or paths (relative to this file)
//   seed: 7                                       # optional: every flight's noise seed (else each scenario's)
//   speed_sweep:
//     scenario: circle_sweep.yaml                 # one circle, lemniscate or waypoints trajectory event
//     speeds: [1.0, 1.5, 2.0]                     # [m/s] strictly increasing; flown until a speed fails
//     fail_on: [path_error_rms, path_error_max]   # trajectory criteria of that scenario that decide it
//     seeds: [21, 1, 2]                           # optional: a speed passes when it passes with every seed
//
// Each key is declared once below (benchmarkKeys()); load() throws ConfigError naming the key
// ("speed_sweep.speeds[2]: must be above speeds[1]").

#include <string>
#include <vector>

#include "sdlqr/batch/spec.hpp"

namespace sdlqr::compare {

struct SpeedSweep {
  std::string scenario_path;          // resolved
  std::vector<double> speeds;         // [m/s]
  std::vector<std::string> fail_on;   // criterion keys
  std::vector<long long> seeds;       // empty: the scenario's own (a benchmark or --seed seed replaces them)
};

struct Experiment {
  std::string name;           // the scenario's name
  std::string scenario_path;  // resolved
};

struct Benchmark {
  std::string path;
  std::vector<std::string> controllers;
  std::vector<Experiment> experiments;
  bool has_sweep = false;
  SpeedSweep sweep;
  long long seed = -1;        // -1: each scenario's own seed

  static Benchmark load(const std::string& path);
};

// The name the speed sweep goes by in --scenarios and in the report.
inline constexpr const char* kSweepName = "speed_sweep";

const std::vector<batch::KeyHelp>& benchmarkKeys();

// --controllers a,b: the benchmark's controllers replaced (each known, named once; ConfigError
// naming --controllers[i]).
void selectControllers(Benchmark& benchmark, const std::string& list);
// --scenarios a,b: only these experiments (and the sweep when kSweepName is among them); a name
// the benchmark does not hold is a ConfigError naming --scenarios[i].
void selectScenarios(Benchmark& benchmark, const std::string& list);

// "a,b" -> {"a", "b"}; empty items kept (the caller names them).
std::vector<std::string> splitList(const std::string& list);

}  // namespace sdlqr::compare
