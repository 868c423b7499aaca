#include "sdlqr/compare/benchmark.hpp"

#include <algorithm>
#include <sstream>

#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/compare/sweep.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::compare {

namespace {

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string scenarioAt(const YAML::Node& node, const std::string& where, const std::string& dir) {
  if (!node.IsScalar() || node.Scalar().empty()) throw ConfigError(where, "expected a scenario name or file");
  try {
    return batch::resolveScenario(node.Scalar(), dir, SDLQR_SOURCE_DIR);
  } catch (const ConfigError& e) {
    throw ConfigError(where, std::string(e.what()).substr(e.key().size() + 2));
  }
}

// A scenario file that loads, with criteria the analysis knows; errors name `where` first.
mission::Scenario loadScenario(const std::string& path, const std::string& where) {
  try {
    mission::Scenario scenario = mission::Scenario::load(path);
    analysis::checkCriteriaKeys(scenario);
    return scenario;
  } catch (const ConfigError& e) {
    throw ConfigError(where + ": " + e.key(), std::string(e.what()).substr(e.key().size() + 2));
  } catch (const std::invalid_argument& e) {
    throw ConfigError(where, e.what());
  }
}

std::vector<Experiment> experimentList(const YAML::Node& node, const std::string& dir) {
  if (!node.IsSequence() || node.size() == 0) throw ConfigError("experiments", "expected a list of scenario names");
  std::vector<Experiment> out;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string where = "experiments[" + std::to_string(i) + "]";
    const std::string path = scenarioAt(node[i], where, dir);
    const std::string name = loadScenario(path, where).name;
    if (name == kSweepName) throw ConfigError(where, std::string("'") + kSweepName + "' names the speed sweep");
    for (const Experiment& e : out) {
      if (e.name == name) throw ConfigError(where, "scenario '" + name + "' named twice");
    }
    out.push_back({name, path});
  }
  return out;
}

std::vector<std::string> criterionList(const YAML::Node& node, const std::string& where,
                                       const mission::Scenario& scenario) {
  if (!node.IsSequence() || node.size() == 0) throw ConfigError(where, "expected a list of criterion keys");
  std::vector<std::string> out;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const std::string key = node[i].IsScalar() ? node[i].Scalar() : std::string();
    const analysis::CriterionSpec* spec = analysis::findCriterion(key);
    if (!spec || spec->scope != analysis::Scope::kTrajectory) {
      throw ConfigError(at, "'" + key + "' is no trajectory criterion (path_error_rms, path_error_max, ...)");
    }
    if (scenario.criteria.count(key) == 0) throw ConfigError(at, "the sweep's scenario sets no limit for '" + key + "'");
    if (std::find(out.begin(), out.end(), key) != out.end()) throw ConfigError(at, "'" + key + "' named twice");
    out.push_back(key);
  }
  return out;
}

long long seedOf(const YAML::Node& node, const std::string& where) {
  long long seed = -1;
  try {
    seed = node.as<long long>();
  } catch (const YAML::Exception&) {
    throw ConfigError(where, "expected an integer >= 0");
  }
  if (seed < 0) throw ConfigError(where, "expected an integer >= 0");
  return seed;
}

std::vector<long long> seedList(const YAML::Node& node, const std::string& where) {
  if (!node.IsSequence() || node.size() == 0) throw ConfigError(where, "expected a list of seeds");
  std::vector<long long> out;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const long long seed = seedOf(node[i], at);
    if (std::find(out.begin(), out.end(), seed) != out.end()) throw ConfigError(at, "seed " + std::to_string(seed) + " named twice");
    out.push_back(seed);
  }
  return out;
}

SpeedSweep sweepOf(const YAML::Node& node, const std::string& dir) {
  const std::string where = "speed_sweep";
  if (!node.IsMap()) throw ConfigError(where, "expected {scenario, speeds, fail_on}");
  const ConfigReader reader(node, where);
  reader.allowOnly({"scenario", "speeds", "fail_on", "seeds"});
  for (const char* key : {"scenario", "speeds", "fail_on"}) {
    if (!node[key]) throw ConfigError(reader.keyPath(key), "missing");
  }
  SpeedSweep sweep;
  sweep.scenario_path = scenarioAt(node["scenario"], where + ".scenario", dir);
  const mission::Scenario scenario = loadScenario(sweep.scenario_path, where + ".scenario");
  sweptEventIndex(scenario, where + ".scenario");
  sweep.speeds = batch::numberList(node["speeds"], where + ".speeds");
  if (sweep.speeds.empty()) throw ConfigError(where + ".speeds", "expected at least one speed");
  for (size_t i = 0; i < sweep.speeds.size(); ++i) {
    const std::string at = where + ".speeds[" + std::to_string(i) + "]";
    if (!(sweep.speeds[i] > 0.0)) throw ConfigError(at, "must be > 0 m/s");
    if (i > 0 && !(sweep.speeds[i] > sweep.speeds[i - 1])) {
      throw ConfigError(at, "must be above speeds[" + std::to_string(i - 1) + "] (the sweep rises)");
    }
  }
  sweep.fail_on = criterionList(node["fail_on"], where + ".fail_on", scenario);
  if (node["seeds"]) sweep.seeds = seedList(node["seeds"], where + ".seeds");
  return sweep;
}

}  // namespace

const std::vector<batch::KeyHelp>& benchmarkKeys() {
  static const std::vector<batch::KeyHelp> keys = {
      {"controllers", "controllers compared: laws of the controller process (lqr.law); default every law"},
      {"experiments", "scenarios each controller flies: names in config/scenarios/, or files (relative to this file)"},
      {"seed", "every flight's noise seed (>= 0); absent: each scenario's own"},
      {"speed_sweep", "{scenario, speeds, fail_on, seeds}: one closed path flown at rising speeds until fail_on fails"},
  };
  return keys;
}

Benchmark Benchmark::load(const std::string& path) {
  const YAML::Node root = loadYamlFile(path);
  if (!root.IsMap()) throw ConfigError(path, "expected a mapping of benchmark keys");
  std::vector<std::string> allowed;
  for (const batch::KeyHelp& k : benchmarkKeys()) allowed.emplace_back(k.key);
  ConfigReader(root, "").allowOnly(allowed);

  Benchmark b;
  b.path = path;
  const std::string dir = directoryOf(path);
  b.controllers = root["controllers"] ? batch::controllerList(root["controllers"], "controllers")
                                      : batch::knownControllers();
  if (!root["experiments"] && !root["speed_sweep"]) {
    throw ConfigError("experiments", "missing: name the experiments (or a speed_sweep)");
  }
  if (root["experiments"]) b.experiments = experimentList(root["experiments"], dir);
  if (root["speed_sweep"]) {
    b.has_sweep = true;
    b.sweep = sweepOf(root["speed_sweep"], dir);
  }
  if (root["seed"]) b.seed = seedOf(root["seed"], "seed");
  return b;
}

std::vector<std::string> splitList(const std::string& list) {
  std::vector<std::string> out;
  std::stringstream in(list);
  for (std::string item; std::getline(in, item, ',');) out.push_back(item);
  if (!list.empty() && list.back() == ',') out.emplace_back();
  return out;
}

void selectControllers(Benchmark& benchmark, const std::string& list) {
  YAML::Node names(YAML::NodeType::Sequence);
  for (const std::string& name : splitList(list)) names.push_back(name);
  benchmark.controllers = batch::controllerList(names, "--controllers");
}

void selectScenarios(Benchmark& benchmark, const std::string& list) {
  const std::vector<std::string> names = splitList(list);
  if (names.empty()) throw ConfigError("--scenarios", "expected a list of experiment names");
  std::vector<Experiment> kept;
  bool sweep = false;
  for (size_t i = 0; i < names.size(); ++i) {
    const std::string& name = names[i];
    const auto it = std::find_if(benchmark.experiments.begin(), benchmark.experiments.end(),
                                 [&](const Experiment& e) { return e.name == name; });
    const bool is_sweep = name == kSweepName && benchmark.has_sweep;
    if (it == benchmark.experiments.end() && !is_sweep) {
      std::string known;
      for (const Experiment& e : benchmark.experiments) known += (known.empty() ? "" : ", ") + e.name;
      if (benchmark.has_sweep) known += (known.empty() ? "" : ", ") + std::string(kSweepName);
      throw ConfigError("--scenarios[" + std::to_string(i) + "]",
                        "no experiment '" + name + "' in " + benchmark.path + " (known: " + known + ")");
    }
    if (is_sweep) {
      sweep = true;
    } else if (std::none_of(kept.begin(), kept.end(), [&](const Experiment& e) { return e.name == name; })) {
      kept.push_back(*it);
    }
  }
  // The benchmark's order, whatever the option's.
  std::vector<Experiment> ordered;
  for (const Experiment& e : benchmark.experiments) {
    if (std::any_of(kept.begin(), kept.end(), [&](const Experiment& k) { return k.name == e.name; })) ordered.push_back(e);
  }
  benchmark.experiments = ordered;
  benchmark.has_sweep = sweep;
}

}  // namespace sdlqr::compare
