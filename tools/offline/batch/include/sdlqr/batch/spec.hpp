#pragma once
// A batch file (`./sdlqr batch SPEC.yaml`): which scenario to fly, with which controllers, how many
// flights from which seed, and the distribution of every perturbed plant parameter:
//
//   scenario: hover_jumps              # a name in config/scenarios/, or a path (relative to this file)
//   controllers: [sdlqr]               # compared on the same draws (flight k: same plant, same noise)
//   flights: 1000
//   seed: 1
//   parameters:                        # keys: sdlqr-batch --list-parameters
//     vehicle.mass: {uniform: [0.23, 0.28]}          # [kg] the plant only: the stack keeps its model
//     vehicle.inertia_diag: {normal: [1.0, 0.1], relative: true}  # x the nominal, every element
//     vehicle.motor_time_constant: {grid: [0.02, 0.03, 0.05]}     # grids combine as a product
//     sim.vio.latency_max_s: {uniform: [0.05, 0.09]}
//     scenario.disturbance_scale: {uniform: [0.5, 2.0]}
//
// Each top-level key is declared once below (specKeys(): key and help; the numbers' ranges in a
// ParamTable), each distribution word once (distributionKeys()). load() throws ConfigError naming
// the key ("parameters.vehicle.mass.uniform[1]: ...").

#include <string>
#include <vector>

#include "sdlqr/batch/plant_parameters.hpp"

namespace sdlqr::batch {

struct Distribution {
  enum class Kind { kUniform, kNormal, kGrid };
  Kind kind = Kind::kUniform;
  double a = 0.0;  // uniform: low; normal: mean
  double b = 0.0;  // uniform: high; normal: standard deviation
  std::vector<double> grid;
  bool relative = false;  // the drawn value multiplies the nominal
};

struct ParameterSpec {
  PlantParameter parameter;
  Distribution distribution;
};

struct KeyHelp {
  const char* key;
  const char* help;
};
const std::vector<KeyHelp>& specKeys();
const std::vector<KeyHelp>& distributionKeys();

// The controllers a batch may name: the controller process's laws (lqr.law of a vehicle file).
const std::vector<std::string>& knownControllers();
// A YAML list of controller names, each known and named once; throws ConfigError naming
// `where[i]` ("controllers[1]: unknown controller 'pid' (known: sdlqr, ...)").
std::vector<std::string> controllerList(const YAML::Node& node, const std::string& where);
// A YAML list of finite numbers; throws ConfigError naming `where` or `where[i]`.
std::vector<double> numberList(const YAML::Node& node, const std::string& where);

struct BatchSpec {
  std::string path;
  std::string scenario_path;  // resolved
  std::vector<std::string> controllers{"sdlqr"};
  int flights = 100;
  long long seed = 1;
  std::vector<ParameterSpec> parameters;
  // Identifies what the batch flies: the spec's, the scenario's and the vehicle file's text. Shards
  // and resumed runs must agree on it.
  std::string fingerprint;

  static BatchSpec load(const std::string& path);
};

// A scenario named like `./sdlqr run` takes it: an existing path, else config/scenarios/<name>.yaml.
std::string resolveScenario(const std::string& name, const std::string& spec_dir, const std::string& source_dir);

}  // namespace sdlqr::batch
