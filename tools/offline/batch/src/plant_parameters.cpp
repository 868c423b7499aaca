#include "sdlqr/batch/plant_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "plant_parameters_rows.hpp"

namespace sdlqr::batch {

ScenarioPerturbation::ScenarioPerturbation() { declaration().setDefaults(*this); }

const ParamTable<ScenarioPerturbation>& ScenarioPerturbation::declaration() {
  static const ParamTable<ScenarioPerturbation> table = scenarioPerturbationRows();
  return table;
}

namespace {

struct SectionOf {
  const char* name;
  Target target;
  const ParamSection* declaration;
};

const std::vector<SectionOf>& sections() {
  static const std::vector<SectionOf> list = {
      {"vehicle", Target::kVehicle, &VehicleParams::declaration()},
      {"sim", Target::kSim, &sim::SimParams::declaration()},
      {"sim", Target::kStress, &sim::SimStress::declaration()},
      {"scenario", Target::kScenario, &ScenarioPerturbation::declaration()},
  };
  return list;
}

bool perturbable(const ParamInfo& info) {
  return (info.kind == ParamKind::kNumber || info.kind == ParamKind::kInteger || info.kind == ParamKind::kList) &&
         info.key != "seed";
}

// "inertia_diag[2]" -> ("inertia_diag", 2); "mass" -> ("mass", -1); -2 for a malformed index.
std::pair<std::string, int> splitElement(const std::string& key) {
  const size_t open = key.find('[');
  if (open == std::string::npos) return {key, -1};
  if (key.back() != ']' || open + 2 > key.size() - 1) return {key.substr(0, open), -2};
  const std::string digits = key.substr(open + 1, key.size() - open - 2);
  if (digits.empty() || !std::all_of(digits.begin(), digits.end(), ::isdigit) || digits.size() > 3) {
    return {key.substr(0, open), -2};
  }
  return {key.substr(0, open), std::stoi(digits)};
}

// A section's values as the YAML a vehicle file would hold.
template <class T>
YAML::Node sectionNode(const T& value) {
  std::ostringstream text;
  YamlWriter writer(text);
  T::declaration().print(value, writer);
  return YAML::Load(text.str());
}

YAML::Node entry(YAML::Node node, const std::string& dotted) {
  std::istringstream parts(dotted);
  std::string part;
  while (std::getline(parts, part, '.')) node.reset(node[part]);
  return node;
}

void setValue(YAML::Node section, const PlantParameter& p, double value) {
  YAML::Node node = entry(section, p.section_key);
  auto text = [&](double v) {
    return p.info.kind == ParamKind::kInteger ? std::to_string(std::llround(v)) : yamlNumber(v);
  };
  if (p.info.kind != ParamKind::kList) {
    node = text(value);
  } else if (p.element >= 0) {
    node[p.element] = text(value);
  } else {
    for (int i = 0; i < p.info.size; ++i) node[i] = text(node[i].as<double>() * value);
  }
}

template <class T>
T loadSection(const T& nominal, const char* name, Target target, const std::vector<PlantParameter>& parameters,
              const std::vector<double>& values) {
  YAML::Node node;
  bool changed = false;
  for (size_t i = 0; i < parameters.size(); ++i) {
    if (parameters[i].target != target) continue;
    if (!changed) node = sectionNode(nominal);
    changed = true;
    setValue(node, parameters[i], values[i]);
  }
  return changed ? T::declaration().load(ConfigReader(node, name)) : nominal;
}

// The section's parameter `name`; nullopt when the section has none of that name.
std::optional<PlantParameter> parameterOf(const SectionOf& s, const std::string& key, const std::string& name,
                                          int element, const std::string& where) {
  for (const ParamInfo& info : s.declaration->params()) {
    if (info.key != name) continue;
    if (!perturbable(info)) throw ConfigError(where, "not a perturbable number (the batch seeds every flight itself)");
    if (element >= 0 && (info.kind != ParamKind::kList || element >= info.size)) {
      throw ConfigError(where, info.kind == ParamKind::kList
                                   ? "index beyond the list's " + std::to_string(info.size) + " elements"
                                   : "not a list: no index");
    }
    return PlantParameter{key, s.target, name, element, info};
  }
  return std::nullopt;
}

}  // namespace

PlantParameter findPlantParameter(const std::string& key, const std::string& where) {
  const size_t dot = key.find('.');
  const std::string section = key.substr(0, dot);
  const bool known = std::any_of(sections().begin(), sections().end(),
                                 [&](const SectionOf& s) { return section == s.name; });
  if (dot == std::string::npos || !known) {
    throw ConfigError(where, "expected vehicle.<key>, sim.<key> or scenario.<key> (sdlqr-batch --list-parameters)");
  }
  const auto [name, element] = splitElement(key.substr(dot + 1));
  if (element == -2) throw ConfigError(where, "expected an element index as in inertia_diag[2]");
  for (const SectionOf& s : sections()) {
    if (section != s.name) continue;
    if (const auto found = parameterOf(s, key, name, element, where)) return *found;
  }
  throw ConfigError(where, "no such key in the " + section + " section (sdlqr-batch --list-parameters)");
}

std::vector<PlantParameter> listPlantParameters() {
  std::vector<PlantParameter> out;
  for (const SectionOf& s : sections()) {
    for (const ParamInfo& info : s.declaration->params()) {
      if (perturbable(info)) out.push_back({std::string(s.name) + "." + info.key, s.target, info.key, -1, info});
    }
  }
  return out;
}

double nominalValue(const PlantParameter& parameter, const closedloop::StackConfig& config, const sim::SimStress& stress) {
  YAML::Node section;
  switch (parameter.target) {
    case Target::kVehicle: section = sectionNode(config.vehicle); break;
    case Target::kSim: section = sectionNode(config.sim); break;
    case Target::kStress: section = sectionNode(stress); break;
    case Target::kScenario: section = sectionNode(ScenarioPerturbation()); break;
  }
  const YAML::Node node = entry(section, parameter.section_key);
  return parameter.info.kind == ParamKind::kList ? node[std::max(parameter.element, 0)].as<double>()
                                                 : node.as<double>();
}

FlightWorld perturbedWorld(const closedloop::StackConfig& config, const mission::Scenario& scenario,
                           const std::vector<PlantParameter>& parameters, const std::vector<double>& values) {
  FlightWorld world{{loadSection(config.vehicle, "vehicle", Target::kVehicle, parameters, values),
                     loadSection(config.sim, "sim", Target::kSim, parameters, values)},
                    scenario};
  const ScenarioPerturbation perturbation =
      loadSection(ScenarioPerturbation(), "scenario", Target::kScenario, parameters, values);
  world.scenario = perturbedScenario(scenario, perturbation);
  world.scenario.sim = loadSection(scenario.sim, "sim", Target::kStress, parameters, values);
  return world;
}

YAML::Node stressNode(const sim::SimStress& stress) { return sectionNode(stress); }

mission::Scenario perturbedScenario(const mission::Scenario& scenario, const ScenarioPerturbation& perturbation) {
  mission::Scenario out = scenario;
  for (mission::ScenarioEvent& event : out.events) {
    if (event.kind != mission::ScenarioEvent::Kind::kDisturbance) continue;
    event.at = std::max(0.0, event.at + perturbation.disturbance_delay);
    event.disturbance.force *= perturbation.disturbance_scale;
    event.disturbance.torque *= perturbation.disturbance_scale;
  }
  std::stable_sort(out.events.begin(), out.events.end(),
                   [](const mission::ScenarioEvent& a, const mission::ScenarioEvent& b) { return a.at < b.at; });
  return out;
}

}  // namespace sdlqr::batch
