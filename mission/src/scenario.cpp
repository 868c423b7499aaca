#include "sdlqr/mission/scenario.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

#include "sdlqr/math/in_flight.hpp"
#include "sdlqr/math/vehicle.hpp"

namespace sdlqr::mission {

namespace {

// The value of the name at `key` among `names` (the first when the key is absent); any other name
// is a ConfigError at the key saying `expected`.
template <class E>
E readChoice(const ConfigReader& reader, const char* key, std::initializer_list<std::pair<const char*, E>> names,
             const char* expected) {
  std::string name = names.begin()->first;
  reader.read(key, name);
  for (const auto& [candidate, value] : names) {
    if (name == candidate) return value;
  }
  throw ConfigError(reader.keyPath(key), expected);
}

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

std::string resolve(const std::string& base_dir, const std::string& path) {
  if (path.empty() || path[0] == '/') return path;
  return base_dir + "/" + path;
}

Command parseCommand(const ConfigReader& event, const std::string& name) {
  Command command;
  if (name == "arm") {
    command.command = CommandType::kArm;
  } else if (name == "disarm") {
    command.command = CommandType::kDisarm;
  } else if (name == "takeoff") {
    command.command = CommandType::kTakeoff;
    double height = 1.0;
    event.read("height", height);
    if (!(height > 0.0 && height <= 20.0)) throw ConfigError(event.keyPath("height"), "must be in (0, 20] m");
    command.position = Vec3(0.0, 0.0, height);
  } else if (name == "goto") {
    command.command = CommandType::kGoto;
    if (!event.has("position")) throw ConfigError(event.keyPath("position"), "goto needs a position [x, y, z]");
    event.read("position", command.position);
    event.read("yaw", command.yaw);
  } else if (name == "land") {
    command.command = CommandType::kLand;
  } else {
    throw ConfigError(event.keyPath("command"), "expected arm, disarm, takeoff, goto or land, got '" + name + "'");
  }
  return command;
}

Disturbance parseDisturbance(const ConfigReader& d) {
  d.allowOnly({"force", "torque", "duration", "mode", "hold_position", "stiffness", "damping"});
  Disturbance out;
  d.read("force", out.force);
  d.read("torque", out.torque);
  d.read("duration", out.duration);
  if (!(out.duration > 0.0 && out.duration <= 60.0)) throw ConfigError(d.keyPath("duration"), "must be in (0, 60] s");
  if (out.force.norm() > 50.0) throw ConfigError(d.keyPath("force"), "magnitude above 50 N");
  if (out.torque.norm() > 5.0) throw ConfigError(d.keyPath("torque"), "magnitude above 5 N m");
  out.mode = readChoice<DisturbanceMode>(d, "mode", {{"force", DisturbanceMode::kForce}, {"hold", DisturbanceMode::kHold}},
                                        "expected force or hold");
  if (out.mode == DisturbanceMode::kHold) {
    if (!d.has("hold_position")) throw ConfigError(d.keyPath("hold_position"), "hold needs a position");
    d.read("hold_position", out.hold_position);
    out.hold_stiffness = 20.0;
    out.hold_damping = 2.0;
    d.read("stiffness", out.hold_stiffness);
    d.read("damping", out.hold_damping);
    if (!(out.hold_stiffness >= 0.0 && out.hold_stiffness <= 1000.0)) {
      throw ConfigError(d.keyPath("stiffness"), "must be in [0, 1000] N/m");
    }
    if (!(out.hold_damping >= 0.0 && out.hold_damping <= 100.0)) {
      throw ConfigError(d.keyPath("damping"), "must be in [0, 100] N s/m");
    }
  }
  return out;
}

// "q_diag and r_diag", "omega_max, c_min and c_max": the keys of one PARAMS group.
std::string groupKeys(int32_t group) {
  std::vector<std::string> keys;
  for (const InFlightParam& param : inFlightParams()) {
    if (param.info.in_flight == group) keys.push_back(param.info.key);
  }
  std::string text;
  for (size_t i = 0; i < keys.size(); ++i) text += (i == 0 ? "" : i + 1 == keys.size() ? " and " : ", ") + keys[i];
  return text;
}

// The keys declared in flight (sdlqr/math/in_flight.hpp), a group's keys all or none, each read
// as its declaration reads it; the values then pass the one check of every PARAMS update.
ParamsUpdate parseParams(const ConfigReader& p) {
  std::vector<std::string> allowed;
  for (const InFlightParam& param : inFlightParams()) allowed.push_back(param.info.key);
  p.allowOnly(allowed);
  ParamsUpdate out;
  for (const InFlightParam& param : inFlightParams()) {
    if (!p.has(param.info.key)) continue;
    for (const InFlightParam& other : inFlightParams()) {
      if (other.info.in_flight == param.info.in_flight && !p.has(other.info.key)) {
        throw ConfigError(p.path(), groupKeys(param.info.in_flight) + " go together");
      }
    }
    out.field_mask |= param.info.in_flight;
    setInFlightValues(out, param.info.key, param.read(p, param.info.key));
  }
  if (out.field_mask == 0) throw ConfigError(p.path(), "sets nothing");
  // Whether the rotors lift a mass is the bodyrate loop's check.
  const InFlightCheck check = checkInFlight(out);
  if (!check.ok()) throw ConfigError(p.keyPath(check.key), check.reason);
  return out;
}

bool isSpeedPath(const std::string& generator) {
  return generator == "circle" || generator == "lemniscate" || generator == "waypoints";
}

void parseSpeedPath(const ConfigReader& t, const std::string& base_dir, TrajectoryRequest& out) {
  if (out.generator == "waypoints") {
    if (!t.has("waypoints")) throw ConfigError(t.keyPath("waypoints"), "waypoints needs a YAML or CSV file");
    t.read("waypoints", out.waypoints_path);
    out.waypoints_path = resolve(base_dir, out.waypoints_path);
  } else if (!t.has("speed")) {
    throw ConfigError(t.keyPath("speed"), out.generator + " needs a speed [m/s]");
  }
  if (t.has("speed")) {
    t.read("speed", out.speed);
    if (!(out.speed > 0.0 && out.speed <= 30.0)) throw ConfigError(t.keyPath("speed"), "must be in (0, 30] m/s");
  }
  t.read("size", out.size);
  if (!(out.size > 0.0 && out.size <= 100.0)) throw ConfigError(t.keyPath("size"), "must be in (0, 100] m");
  t.read("center", out.center);
  if (t.has("v_max")) {
    t.read("v_max", out.v_max);
    if (!(out.v_max > 0.0 && out.v_max <= 30.0)) throw ConfigError(t.keyPath("v_max"), "must be in (0, 30] m/s");
  }
}

TrajectoryRequest parseTrajectory(const ConfigReader& t, const std::string& base_dir) {
  t.allowOnly({"generator", "csv", "laps", "tracking", "height_offset", "sample_dt", "waypoints", "speed", "size",
               "center", "v_max", "on_infeasible"});
  TrajectoryRequest out;
  t.read("generator", out.generator);
  if (t.has("csv")) {
    t.read("csv", out.csv_path);
    out.csv_path = resolve(base_dir, out.csv_path);
    if (out.generator.empty()) out.generator = "csv";
  }
  if (out.generator != "minsnap_fast" && out.generator != "minsnap_slow" && out.generator != "ellipse" &&
      out.generator != "csv" && !isSpeedPath(out.generator)) {
    throw ConfigError(t.keyPath("generator"),
                      "expected minsnap_fast, minsnap_slow, ellipse, csv, circle, lemniscate or waypoints");
  }
  if (out.generator == "csv" && out.csv_path.empty()) throw ConfigError(t.keyPath("csv"), "csv needs a file");
  if (isSpeedPath(out.generator)) {
    parseSpeedPath(t, base_dir, out);
  } else {
    for (const char* key : {"waypoints", "speed", "size", "center", "v_max"}) {
      if (t.has(key)) throw ConfigError(t.keyPath(key), "only for circle, lemniscate and waypoints");
    }
  }
  out.on_infeasible = readChoice<OnInfeasible>(
      t, "on_infeasible", {{"refuse", OnInfeasible::kRefuse}, {"scale", OnInfeasible::kScale}, {"fly", OnInfeasible::kFly}},
      "expected refuse, scale or fly");
  if (t.has("laps")) {
    t.read("laps", out.laps);
    if (out.laps < 1 || out.laps > 100) throw ConfigError(t.keyPath("laps"), "must be in [1, 100]");
  }
  out.tracking = readChoice<ReferenceMode>(
      t, "tracking", {{"spatial", ReferenceMode::kSpatial}, {"temporal", ReferenceMode::kTemporal}},
      "expected spatial or temporal");
  if (t.has("height_offset")) {
    t.read("height_offset", out.height_offset);
    if (!(out.height_offset >= 0.0 && out.height_offset <= 50.0)) {
      throw ConfigError(t.keyPath("height_offset"), "must be in [0, 50] m");
    }
  }
  if (t.has("sample_dt")) {
    t.read("sample_dt", out.sample_dt);
    if (!(out.sample_dt >= 0.001 && out.sample_dt <= 1.0)) {
      throw ConfigError(t.keyPath("sample_dt"), "must be in [0.001, 1] s");
    }
  }
  return out;
}

}  // namespace

Scenario Scenario::load(const std::string& path) {
  const YAML::Node root_node = loadYamlFile(path);
  const ConfigReader root(root_node, "");
  root.allowOnly(
      {"name", "description", "vehicle", "seed", "duration", "rate", "events", "criteria", "sim", "throw_mode"});
  Scenario s;
  s.path = path;
  const std::string base_dir = directoryOf(path);
  s.name = path.substr(path.find_last_of('/') == std::string::npos ? 0 : path.find_last_of('/') + 1);
  if (s.name.size() > 5 && s.name.substr(s.name.size() - 5) == ".yaml") s.name.resize(s.name.size() - 5);
  root.read("name", s.name);
  for (char c : s.name) {
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-')) {
      throw ConfigError("name", "use letters, digits, '_' or '-' only");
    }
  }
  root.read("description", s.description);
  std::string vehicle = "../quad255.yaml";
  root.read("vehicle", vehicle);
  s.vehicle_path = resolve(base_dir, vehicle);
  root.read("seed", s.seed);
  root.read("duration", s.duration);
  if (!(s.duration > 0.0 && s.duration <= 3600.0)) throw ConfigError("duration", "must be in (0, 3600] s");
  root.read("rate", s.rate);
  if (!(s.rate > 0.0 && s.rate <= 100.0)) throw ConfigError("rate", "must be in (0, 100]");

  if (root.has("events")) {
    const YAML::Node events = root_node["events"];
    if (!events.IsSequence()) throw ConfigError("events", "expected a list");
    for (size_t i = 0; i < events.size(); ++i) {
      const ConfigReader e(events[i], "events[" + std::to_string(i) + "]");
      e.allowOnly({"at", "command", "height", "position", "yaw", "disturbance", "params", "trajectory", "label"});
      ScenarioEvent event;
      if (!e.has("at")) throw ConfigError(e.keyPath("at"), "every event needs a time");
      e.read("at", event.at);
      if (!(event.at >= 0.0 && event.at <= s.duration)) throw ConfigError(e.keyPath("at"), "must be in [0, duration]");
      e.read("label", event.label);
      const int kinds = (e.has("command") ? 1 : 0) + (e.has("disturbance") ? 1 : 0) + (e.has("params") ? 1 : 0) +
                        (e.has("trajectory") ? 1 : 0);
      if (kinds != 1) throw ConfigError(e.path(), "needs exactly one of command, disturbance, params, trajectory");
      if (e.has("command")) {
        std::string name;
        e.read("command", name);
        event.kind = ScenarioEvent::Kind::kCommand;
        event.command = parseCommand(e, name);
      } else if (e.has("disturbance")) {
        event.kind = ScenarioEvent::Kind::kDisturbance;
        event.disturbance = parseDisturbance(e.child("disturbance"));
      } else if (e.has("params")) {
        event.kind = ScenarioEvent::Kind::kParams;
        event.params = parseParams(e.child("params"));
      } else {
        event.kind = ScenarioEvent::Kind::kTrajectory;
        event.trajectory = parseTrajectory(e.child("trajectory"), base_dir);
      }
      s.events.push_back(event);
    }
  }
  s.sim = sim::SimStress::load(root.child("sim"));
  s.throw_mode = ThrowModeParams::declaration().load(root.child("throw_mode"));
  std::stable_sort(s.events.begin(), s.events.end(),
                   [](const ScenarioEvent& a, const ScenarioEvent& b) { return a.at < b.at; });

  if (root.has("criteria")) {
    const YAML::Node criteria = root_node["criteria"];
    if (!criteria.IsMap()) throw ConfigError("criteria", "expected a mapping of name: number");
    const ConfigReader c(criteria, "criteria");
    for (const auto& entry : criteria) {
      const std::string key = entry.first.as<std::string>();
      double value = 0.0;
      c.read(key, value);
      s.criteria[key] = value;
    }
  }
  return s;
}

double Scenario::criterion(const std::string& key, double fallback) const {
  const auto it = criteria.find(key);
  return it == criteria.end() ? fallback : it->second;
}

}  // namespace sdlqr::mission
