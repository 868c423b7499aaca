#pragma once
// The parameters a batch may perturb: every number of the vehicle file's `vehicle:` and `sim:`
// sections and of the scenario's `sim:` stressors (plant mismatch, wind, airborne start, throw;
// sim/stress_params.hpp) — keys, units and accepted ranges from their ParamTable declarations,
// both `sim:` sections under one "sim." prefix (no key is in both) — given to the simulator only — the estimator, gain solver, controller and bodyrate loop keep the nominal
// vehicle — and the scenario's disturbances (ScenarioPerturbation). A list is perturbed one
// element at a time ("vehicle.inertia_diag[2]") or, relative, all elements by one factor.
// sim.seed is not a parameter: the batch gives every flight a seed of its own.

#include <string>
#include <vector>

#include "sdlqr/closedloop/closed_loop.hpp"
#include "sdlqr/config/param_table.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::batch {

// What a batch may change about a scenario's disturbances (`scenario.` keys).
struct ScenarioPerturbation {
  double disturbance_scale;  // [-] every disturbance's force and torque times this
  double disturbance_delay;  // [s] every disturbance this much later
  ScenarioPerturbation();
  static const ParamTable<ScenarioPerturbation>& declaration();
};

enum class Target { kVehicle, kSim, kStress, kScenario };

struct PlantParameter {
  std::string key;          // as the batch file names it: "vehicle.inertia_diag[2]"
  Target target = Target::kVehicle;
  std::string section_key;  // within its section: "inertia_diag", "vio.latency_max_s", "wind.gust_std"
  int element = -1;         // of a list; -1: the whole list (relative only) or a number
  ParamInfo info;
};

// Throws ConfigError naming `where` when the key is not a perturbable parameter.
PlantParameter findPlantParameter(const std::string& key, const std::string& where);
// Every perturbable key with its declaration (lists once, as their whole-list key).
std::vector<PlantParameter> listPlantParameters();

// One flight's world: the simulator's plant and the scenario as flown.
struct FlightWorld {
  closedloop::Plant plant;
  mission::Scenario scenario;
};

// The nominal value of a parameter (of a whole list: its first element) in `config` and the
// scenario's stressors `stress`.
double nominalValue(const PlantParameter& parameter, const closedloop::StackConfig& config, const sim::SimStress& stress);

// The nominal world with each parameter set to its value (a whole list: every element times the
// value); throws ConfigError naming the parameter's key when the result is not a valid plant.
FlightWorld perturbedWorld(const closedloop::StackConfig& config, const mission::Scenario& scenario,
                           const std::vector<PlantParameter>& parameters, const std::vector<double>& values);

// The stressors as a scenario's `sim:` mapping holds them.
YAML::Node stressNode(const sim::SimStress& stress);

// The scenario with its disturbances scaled and delayed; events stay sorted by time.
mission::Scenario perturbedScenario(const mission::Scenario& scenario, const ScenarioPerturbation& perturbation);

}  // namespace sdlqr::batch
