#include "sdlqr/compare/bus_flights.hpp"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::compare {

namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out.flush()) throw ConfigError(path.string(), "cannot write");
}

std::string emitted(const YAML::Node& node) {
  YAML::Emitter out;
  out << node;
  return std::string(out.c_str()) + "\n";
}

// A trajectory file named relative to the experiment keeps pointing at it from the new folder.
void absoluteTrajectoryFiles(YAML::Node scenario, const fs::path& experiment_dir) {
  for (YAML::Node event : scenario["events"]) {
    YAML::Node trajectory = event["trajectory"];
    if (!trajectory || !trajectory.IsMap()) continue;
    for (const char* key : {"csv", "waypoints"}) {
      if (trajectory[key] && trajectory[key].IsScalar() && fs::path(trajectory[key].Scalar()).is_relative()) {
        trajectory[key] = fs::absolute(experiment_dir / trajectory[key].Scalar()).lexically_normal().string();
      }
    }
  }
}

void writeFlight(const Benchmark& benchmark, const Experiment& experiment, const std::string& controller,
                 const fs::path& folder) {
  const mission::Scenario scenario = mission::Scenario::load(experiment.scenario_path);
  ControlLaw law;
  if (!parseControlLaw(controller, law)) throw ConfigError("controllers", "unknown controller '" + controller + "'");
  fs::create_directories(folder);
  YAML::Node vehicle = YAML::Clone(loadYamlFile(scenario.vehicle_path));
  vehicle["lqr"]["law"] = toString(law);
  writeText(folder / "vehicle.yaml", "# " + scenario.vehicle_path + " flying " + controller + " (sdlqr-compare --bus-files)\n" +
                                         emitted(vehicle));
  YAML::Node text = YAML::Clone(loadYamlFile(experiment.scenario_path));
  text["vehicle"] = fs::absolute(folder / "vehicle.yaml").string();
  if (benchmark.seed >= 0) text["seed"] = benchmark.seed;
  absoluteTrajectoryFiles(text, fs::path(experiment.scenario_path).parent_path());
  writeText(folder / "scenario.yaml", "# " + fs::path(experiment.scenario_path).lexically_normal().string() + " for " + controller + " (sdlqr-compare --bus-files)\n" +
                                          emitted(text));
}

}  // namespace

int writeBusFlights(const Benchmark& benchmark, const std::string& dir) {
  fs::create_directories(dir);
  std::string plan;
  int flights = 0;
  for (const std::string& controller : benchmark.controllers) {
    for (const Experiment& experiment : benchmark.experiments) {
      const fs::path folder = fs::path(dir) / controller / experiment.name;
      writeFlight(benchmark, experiment, controller, folder);
      plan += controller + " " + experiment.name + " " + fs::absolute(folder).string() + "\n";
      ++flights;
    }
  }
  writeText(fs::path(dir) / "plan.txt", plan);
  return flights;
}

}  // namespace sdlqr::compare
