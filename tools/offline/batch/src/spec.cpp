#include "sdlqr/batch/spec.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "sdlqr/math/lqr_params.hpp"

#include "file_text.hpp"

namespace sdlqr::batch {

namespace {

// The numbers of a batch file, with their ranges.
struct SpecNumbers {
  int flights;
  long long seed;
  SpecNumbers() { declaration().setDefaults(*this); }
  static const ParamTable<SpecNumbers>& declaration();
};

}  // namespace

}  // namespace sdlqr::batch

// The rows of SpecNumbers (params/spec.yaml, which names no header: the struct is this file's).
#include "spec_rows.hpp"

namespace sdlqr::batch {

namespace {

const ParamTable<SpecNumbers>& SpecNumbers::declaration() {
  static const ParamTable<SpecNumbers> table = specNumbersRows();
  return table;
}

bool isFile(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string fnv1a(const std::string& text) {
  uint64_t hash = 1469598103934665603ull;
  for (unsigned char c : text) hash = (hash ^ c) * 1099511628211ull;
  std::ostringstream out;
  out << std::hex << hash;
  return out.str();
}

void checkInRange(const PlantParameter& p, const Distribution& d, double value, const std::string& where) {
  if (d.relative) {
    if (!(value >= 0.0)) throw ConfigError(where, "a relative factor must be >= 0");
    return;
  }
  if (!p.info.range.contains(value)) throw ConfigError(where, p.info.range.rule(p.info.unit) + " (" + p.key + ")");
  if (p.info.kind == ParamKind::kInteger && value != std::round(value)) throw ConfigError(where, "expected an integer");
}

Distribution distribution(const PlantParameter& p, const YAML::Node& node, const std::string& where) {
  if (!node.IsMap()) throw ConfigError(where, "expected {uniform: [low, high]}, {normal: [mean, std]} or {grid: [...]}");
  const ConfigReader reader(node, where);
  std::vector<std::string> allowed;
  for (const KeyHelp& k : distributionKeys()) allowed.emplace_back(k.key);
  reader.allowOnly(allowed);
  Distribution d;
  reader.read("relative", d.relative);
  int kinds = 0;
  if (node["uniform"]) {
    ++kinds;
    const std::vector<double> v = numberList(node["uniform"], where + ".uniform");
    if (v.size() != 2) throw ConfigError(where + ".uniform", "expected [low, high]");
    if (!(v[0] <= v[1])) throw ConfigError(where + ".uniform[1]", "high must be >= low");
    d = {Distribution::Kind::kUniform, v[0], v[1], {}, d.relative};
    checkInRange(p, d, v[0], where + ".uniform[0]");
    checkInRange(p, d, v[1], where + ".uniform[1]");
  }
  if (node["normal"]) {
    ++kinds;
    const std::vector<double> v = numberList(node["normal"], where + ".normal");
    if (v.size() != 2) throw ConfigError(where + ".normal", "expected [mean, std]");
    if (!(v[1] >= 0.0)) throw ConfigError(where + ".normal[1]", "the standard deviation must be >= 0");
    d = {Distribution::Kind::kNormal, v[0], v[1], {}, d.relative};
    checkInRange(p, d, v[0], where + ".normal[0]");
  }
  if (node["grid"]) {
    ++kinds;
    const std::vector<double> v = numberList(node["grid"], where + ".grid");
    if (v.empty()) throw ConfigError(where + ".grid", "expected at least one value");
    d = {Distribution::Kind::kGrid, 0.0, 0.0, v, d.relative};
    for (size_t i = 0; i < v.size(); ++i) checkInRange(p, d, v[i], where + ".grid[" + std::to_string(i) + "]");
  }
  if (kinds != 1) throw ConfigError(where, "expected exactly one of uniform, normal, grid");
  if (p.info.kind == ParamKind::kList && p.element < 0 && !d.relative) {
    throw ConfigError(where, "a list: name one element (" + p.key + "[0]) or scale every element (relative: true)");
  }
  return d;
}

}  // namespace

const std::vector<KeyHelp>& specKeys() {
  static const std::vector<KeyHelp> keys = {
      {"scenario", "a name in config/scenarios/, or a scenario file (relative to the batch file)"},
      {"controllers", "controllers compared on the same draws: laws of the controller process (lqr.law), default [sdlqr]"},
      {"flights", "flights per controller (1 .. 10000000)"},
      {"seed", "seed of every draw and of every flight's noise (>= 0)"},
      {"parameters", "perturbed parameter -> distribution (sdlqr-batch --list-parameters)"},
  };
  return keys;
}

const std::vector<KeyHelp>& distributionKeys() {
  static const std::vector<KeyHelp> keys = {
      {"uniform", "[low, high]: uniform between them"},
      {"normal", "[mean, std]: normal, drawn again while outside the parameter's range"},
      {"grid", "[v0, v1, ...]: every value; several grids combine as a product, flight k takes combination k mod size"},
      {"relative", "true: values are factors of the nominal (a whole list: every element)"},
  };
  return keys;
}

const std::vector<std::string>& knownControllers() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (ControlLaw law : controlLaws()) out.emplace_back(toString(law));
    return out;
  }();
  return names;
}

std::vector<double> numberList(const YAML::Node& node, const std::string& where) {
  if (!node.IsSequence()) throw ConfigError(where, "expected a list of numbers");
  std::vector<double> out;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    double v = 0.0;
    try {
      v = node[i].as<double>();
    } catch (const YAML::Exception&) {
      throw ConfigError(at, "expected a number");
    }
    if (!std::isfinite(v)) throw ConfigError(at, "must be finite");
    out.push_back(v);
  }
  return out;
}

std::vector<std::string> controllerList(const YAML::Node& node, const std::string& where) {
  if (!node.IsSequence() || node.size() == 0) throw ConfigError(where, "expected a list of controller names, e.g. [sdlqr]");
  std::vector<std::string> out;
  for (size_t i = 0; i < node.size(); ++i) {
    const std::string at = where + "[" + std::to_string(i) + "]";
    const std::string name = node[i].IsScalar() ? node[i].Scalar() : std::string();
    const auto& known = knownControllers();
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw ConfigError(at, "unknown controller '" + name + "' (known: " + list + ")");
    }
    if (std::find(out.begin(), out.end(), name) != out.end()) throw ConfigError(at, "'" + name + "' named twice");
    out.push_back(name);
  }
  return out;
}

std::string resolveScenario(const std::string& name, const std::string& spec_dir, const std::string& source_dir) {
  if (!name.empty() && name[0] == '/' && isFile(name)) return name;
  if (isFile(spec_dir + "/" + name)) return spec_dir + "/" + name;
  const std::string named = source_dir + "/config/scenarios/" + name + ".yaml";
  if (isFile(named)) return named;
  throw ConfigError("scenario", "no scenario file or name '" + name + "'");
}

BatchSpec BatchSpec::load(const std::string& path) {
  const YAML::Node root = loadYamlFile(path);
  if (!root.IsMap()) throw ConfigError(path, "expected a mapping of batch keys");
  const ConfigReader reader(root, "");
  std::vector<std::string> allowed;
  for (const KeyHelp& k : specKeys()) allowed.emplace_back(k.key);
  reader.allowOnly(allowed);

  BatchSpec spec;
  spec.path = path;
  YAML::Node numbers_node(YAML::NodeType::Map);
  for (const char* key : {"flights", "seed"}) {
    if (root[key]) numbers_node[key] = root[key];
  }
  const SpecNumbers numbers = SpecNumbers::declaration().load(ConfigReader(numbers_node, ""));
  spec.flights = numbers.flights;
  spec.seed = numbers.seed;

  if (!root["scenario"]) throw ConfigError("scenario", "missing: name the scenario to fly");
  std::string scenario;
  reader.read("scenario", scenario);
  spec.scenario_path = resolveScenario(scenario, directoryOf(path), SDLQR_SOURCE_DIR);
  if (root["controllers"]) spec.controllers = controllerList(root["controllers"], "controllers");

  if (root["parameters"]) {
    const YAML::Node params = root["parameters"];
    if (!params.IsMap()) throw ConfigError("parameters", "expected a mapping: parameter key -> distribution");
    for (const auto& item : params) {
      const std::string key = item.first.Scalar();
      const std::string where = "parameters." + key;
      const PlantParameter parameter = findPlantParameter(key, where);
      for (const ParameterSpec& seen : spec.parameters) {
        if (seen.parameter.key == key) throw ConfigError(where, "named twice");
      }
      spec.parameters.push_back({parameter, distribution(parameter, item.second, where)});
    }
  }
  const mission::Scenario loaded = mission::Scenario::load(spec.scenario_path);
  spec.fingerprint = fnv1a(detail::fileText(path) + '\0' + detail::fileText(spec.scenario_path) + '\0' +
                           detail::fileText(loaded.vehicle_path));
  return spec;
}

}  // namespace sdlqr::batch
