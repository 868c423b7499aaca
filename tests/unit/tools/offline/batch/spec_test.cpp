// Batch files: every key checked, one error naming the key for each kind of mistake.
#include <gtest/gtest.h>

#include <fstream>

#include "sdlqr/batch/spec.hpp"
#include "batch_test_dir.hpp"

#include "config_errors.hpp"

namespace sdlqr::batch {
namespace {

using test::kDir;


std::string writeSpec(const std::string& name, const std::string& text) {
  const std::string path = std::string(SDLQR_BINARY_DIR) + "/batch_spec_" + name + ".yaml";
  std::ofstream(path) << text;
  return path;
}

// The key a bad batch file is refused with.
std::string refusedKey(const std::string& name, const std::string& body) {
  return testing::keyBlamedBy([&] { BatchSpec::load(writeSpec(name, "scenario: " + kDir + "/short_hover.yaml\n" + body)); });
}

TEST(BatchSpec, LoadsTheSmallBatch) {
  const BatchSpec spec = BatchSpec::load(kDir + "/small_batch.yaml");
  EXPECT_EQ(spec.flights, 20);
  EXPECT_EQ(spec.seed, 11);
  ASSERT_EQ(spec.parameters.size(), 7u);
  EXPECT_EQ(spec.parameters[0].parameter.key, "vehicle.mass");
  EXPECT_EQ(spec.parameters[0].parameter.target, Target::kVehicle);
  EXPECT_EQ(spec.parameters[1].distribution.kind, Distribution::Kind::kNormal);
  EXPECT_TRUE(spec.parameters[1].distribution.relative);
  EXPECT_EQ(spec.parameters[2].distribution.grid.size(), 2u);
  EXPECT_EQ(spec.parameters[3].parameter.target, Target::kSim);
  EXPECT_EQ(spec.parameters[5].parameter.target, Target::kScenario);
  EXPECT_EQ(spec.controllers, std::vector<std::string>{"sdlqr"});
  EXPECT_FALSE(spec.fingerprint.empty());
}

TEST(BatchSpec, NamesEveryLawOfTheControllerAndTheScenariosStressors) {
  const BatchSpec spec = BatchSpec::load(kDir + "/controllers_in_wind.yaml");
  EXPECT_EQ(spec.controllers, (std::vector<std::string>{"sdlqr", "hover_lqr", "geometric"}));
  ASSERT_EQ(spec.parameters.size(), 3u);
  EXPECT_EQ(spec.parameters[0].parameter.target, Target::kStress);
  EXPECT_EQ(spec.parameters[0].parameter.section_key, "wind.steady");
  EXPECT_EQ(spec.parameters[0].parameter.element, 0);
  EXPECT_EQ(refusedKey("all_laws", "controllers: [sdlqr, hover_lqr, geometric, sdlqr_integral, sdlqr_actuator]\n"),
            "<no error>");
  EXPECT_EQ(refusedKey("stress_key", "parameters: {sim.wind.gusts: {uniform: [0, 1]}}\n"), "parameters.sim.wind.gusts");
  EXPECT_EQ(refusedKey("stress_range", "parameters: {sim.plant.thrust_scale: {uniform: [-1, 1]}}\n"),
            "parameters.sim.plant.thrust_scale.uniform[0]");
}

TEST(BatchSpec, RefusesEachMistakeNamingTheKey) {
  EXPECT_EQ(refusedKey("top", "flihgts: 3\n"), "flihgts");
  EXPECT_EQ(refusedKey("flights", "flights: 0\n"), "flights");
  EXPECT_EQ(refusedKey("seed", "seed: -1\n"), "seed");
  EXPECT_EQ(refusedKey("controller", "controllers: [sdlqr, pid]\n"), "controllers[1]");
  EXPECT_EQ(refusedKey("controller_twice", "controllers: [sdlqr, sdlqr]\n"), "controllers[1]");
  EXPECT_EQ(refusedKey("controllers_empty", "controllers: []\n"), "controllers");
  EXPECT_EQ(refusedKey("section", "parameters: {lqr.dt: {uniform: [0.01, 0.02]}}\n"), "parameters.lqr.dt");
  EXPECT_EQ(refusedKey("no_key", "parameters: {vehicle.weight: {uniform: [1, 2]}}\n"), "parameters.vehicle.weight");
  EXPECT_EQ(refusedKey("seed_param", "parameters: {sim.seed: {grid: [1, 2]}}\n"), "parameters.sim.seed");
  EXPECT_EQ(refusedKey("range", "parameters: {vehicle.mass: {uniform: [0.2, -1]}}\n"),
            "parameters.vehicle.mass.uniform[1]");
  EXPECT_EQ(refusedKey("below", "parameters: {vehicle.mass: {uniform: [-0.1, 0.3]}}\n"),
            "parameters.vehicle.mass.uniform[0]");
  EXPECT_EQ(refusedKey("grid_range", "parameters: {sim.vio.rate_hz: {grid: [30, 0]}}\n"),
            "parameters.sim.vio.rate_hz.grid[1]");
  EXPECT_EQ(refusedKey("grid_int", "parameters: {sim.vio.rate_hz: {grid: [30, 20.5]}}\n"),
            "parameters.sim.vio.rate_hz.grid[1]");
  EXPECT_EQ(refusedKey("normal_std", "parameters: {vehicle.mass: {normal: [0.25, -0.01]}}\n"),
            "parameters.vehicle.mass.normal[1]");
  EXPECT_EQ(refusedKey("two_kinds", "parameters: {vehicle.mass: {uniform: [0.2, 0.3], grid: [0.25]}}\n"),
            "parameters.vehicle.mass");
  EXPECT_EQ(refusedKey("kind_typo", "parameters: {vehicle.mass: {uniform: [0.2, 0.3], relatve: true}}\n"),
            "parameters.vehicle.mass.relatve");
  EXPECT_EQ(refusedKey("list", "parameters: {vehicle.inertia_diag: {uniform: [0.001, 0.002]}}\n"),
            "parameters.vehicle.inertia_diag");
  EXPECT_EQ(refusedKey("index", "parameters:\n  vehicle.inertia_diag[3]: {uniform: [0.001, 0.002]}\n"),
            "parameters.vehicle.inertia_diag[3]");
  EXPECT_EQ(refusedKey("number_index", "parameters:\n  vehicle.mass[0]: {uniform: [0.2, 0.3]}\n"),
            "parameters.vehicle.mass[0]");
  EXPECT_EQ(refusedKey("not_number", "parameters: {vehicle.mass: {uniform: [0.2, heavy]}}\n"),
            "parameters.vehicle.mass.uniform[1]");
  EXPECT_EQ(refusedKey("scenario_param", "parameters: {scenario.disturbance_scale: {uniform: [-1, 1]}}\n"),
            "parameters.scenario.disturbance_scale.uniform[0]");
  EXPECT_EQ(refusedKey("relative_factor", "parameters: {vehicle.mass: {uniform: [-0.5, 1.0], relative: true}}\n"),
            "parameters.vehicle.mass.uniform[0]");
  try {
    BatchSpec::load(writeSpec("no_scenario", "scenario: nowhere_to_be_found\n"));
    FAIL() << "accepted a missing scenario";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "scenario");
  }
  // An element of a list and a relative whole list are accepted.
  EXPECT_EQ(refusedKey("element", "parameters:\n  vehicle.inertia_diag[2]: {uniform: [0.0015, 0.0017]}\n"), "<no error>");
  EXPECT_EQ(refusedKey("whole", "parameters: {vehicle.inertia_diag: {grid: [0.9, 1.1], relative: true}}\n"), "<no error>");
}

TEST(BatchSpec, ScenarioByNameFromConfigScenarios) {
  const BatchSpec spec = BatchSpec::load(writeSpec("named", "scenario: hover_jumps\nflights: 2\n"));
  EXPECT_EQ(spec.scenario_path, std::string(SDLQR_SOURCE_DIR) + "/config/scenarios/hover_jumps.yaml");
}

TEST(PlantParameters, ListsTheVehicleSimAndScenarioKeysButNotTheSeed) {
  std::vector<std::string> keys;
  for (const PlantParameter& p : listPlantParameters()) keys.push_back(p.key);
  for (const char* key : {"vehicle.mass", "vehicle.inertia_diag", "vehicle.motor_time_constant", "sim.imu.gyro_noise_density",
                          "sim.vio.latency_max_s", "sim.vio.rate_hz", "sim.initial_yaw", "scenario.disturbance_scale"}) {
    EXPECT_NE(std::find(keys.begin(), keys.end(), key), keys.end()) << key;
  }
  EXPECT_EQ(std::find(keys.begin(), keys.end(), "sim.seed"), keys.end());
}

TEST(PlantParameters, ThePlantChangesAndTheStackKeepsItsModel) {
  const closedloop::StackConfig config;
  mission::Scenario scenario = mission::Scenario::load(kDir + "/short_hover.yaml");
  const std::vector<PlantParameter> parameters = {findPlantParameter("vehicle.mass", "p"),
                                                  findPlantParameter("vehicle.inertia_diag", "p"),
                                                  findPlantParameter("sim.vio.rate_hz", "p"),
                                                  findPlantParameter("scenario.disturbance_scale", "p"),
                                                  findPlantParameter("scenario.disturbance_delay", "p")};
  const FlightWorld world = perturbedWorld(config, scenario, parameters, {0.4, 2.0, 20.0, 3.0, 0.5});
  EXPECT_DOUBLE_EQ(world.plant.vehicle.mass, 0.4);
  EXPECT_DOUBLE_EQ(world.plant.vehicle.inertia_diag.z(), 2.0 * config.vehicle.inertia_diag.z());
  EXPECT_EQ(world.plant.sim.vio.rate_hz, 20);
  EXPECT_DOUBLE_EQ(config.vehicle.mass, 0.255);  // the nominal is untouched
  const auto pull = std::find_if(world.scenario.events.begin(), world.scenario.events.end(), [](const auto& e) {
    return e.kind == mission::ScenarioEvent::Kind::kDisturbance;
  });
  ASSERT_NE(pull, world.scenario.events.end());
  EXPECT_DOUBLE_EQ(pull->at, 8.0);
  EXPECT_DOUBLE_EQ(pull->disturbance.force.y(), 3.0);
  // A value the plant refuses is an error naming the key.
  try {
    perturbedWorld(config, scenario, {parameters[0]}, {-1.0});
    FAIL() << "accepted a negative mass";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "vehicle.mass");
  }
}

}  // namespace
}  // namespace sdlqr::batch
