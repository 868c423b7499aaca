#include "sdlqr/trajectory/waypoint_file.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <istream>

#include "sdlqr/trajectory/trajectory_csv.hpp"

#include "text_fields.hpp"

namespace sdlqr::trajectory {

namespace {

bool parseFinite(const std::string& text, double& out) {
  const std::string field = detail::trimBlanks(text);
  if (field.empty()) return false;
  char* end = nullptr;
  out = std::strtod(field.c_str(), &end);
  return *end == '\0' && std::isfinite(out);
}

Waypoint waypointFromNumbers(const std::vector<double>& v) {
  Waypoint w;
  w.position = Vec3(v[0], v[1], v[2]);
  w.has_yaw = v.size() == 4;
  if (w.has_yaw) w.yaw = v[3];
  return w;
}

}  // namespace

WaypointSpec loadWaypointSpec(const ConfigReader& root, const YAML::Node& node) {
  root.allowOnly({"waypoints", "periodic", "v_max"});
  WaypointSpec spec;
  root.read("periodic", spec.periodic);
  if (root.has("v_max")) {
    root.read("v_max", spec.v_max);
    if (!(spec.v_max > 0.0)) throw ConfigError(root.keyPath("v_max"), "must be > 0");
  }
  const std::string key = root.keyPath("waypoints");
  const YAML::Node list = node["waypoints"];
  if (!list || !list.IsSequence()) throw ConfigError(key, "expected a list of [x, y, z] or [x, y, z, yaw]");
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string item_key = key + "[" + std::to_string(i) + "]";
    const YAML::Node item = list[i];
    if (!item.IsSequence() || (item.size() != 3 && item.size() != 4)) {
      throw ConfigError(item_key, "expected 3 or 4 numbers");
    }
    std::vector<double> values(item.size());
    for (std::size_t c = 0; c < item.size(); ++c) {
      if (!item[c].IsScalar() || !parseFinite(item[c].Scalar(), values[c])) {
        throw ConfigError(item_key + "[" + std::to_string(c) + "]", "expected a finite number");
      }
    }
    spec.waypoints.push_back(waypointFromNumbers(values));
    if (spec.waypoints.back().has_yaw != spec.waypoints.front().has_yaw) {
      throw ConfigError(item_key, "give yaw on every waypoint or on none");
    }
  }
  if (spec.waypoints.size() < 2) throw ConfigError(key, "need at least 2 waypoints");
  return spec;
}

WaypointSpec loadWaypointYaml(const std::string& path) {
  const YAML::Node root = loadYamlFile(path);
  try {
    return loadWaypointSpec(ConfigReader(root, ""), root);
  } catch (const ConfigError& e) {
    // Name the file too: the key alone does not say which file it is in.
    const std::string reason = std::string(e.what()).substr(e.key().size() + 2);
    throw ConfigError(path + ": " + e.key(), reason);
  }
}

std::vector<Waypoint> parseWaypointCsv(std::istream& in, const std::string& name) {
  std::vector<Waypoint> out;
  std::string text;
  int line = 0;
  bool header_allowed = true;
  while (std::getline(in, text)) {
    ++line;
    const std::string trimmed = detail::trimBlanks(text);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    if (header_allowed && (trimmed[0] == 'x' || trimmed[0] == 'X')) {
      header_allowed = false;
      continue;
    }
    header_allowed = false;
    std::vector<double> values;
    std::size_t start = 0;
    while (true) {
      const auto comma = trimmed.find(',', start);
      double value = 0.0;
      const std::string field = trimmed.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      if (!parseFinite(field, value)) {
        throw TrajectoryFileError(name, line, "cannot parse '" + detail::trimBlanks(field) + "' as a finite number");
      }
      values.push_back(value);
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    if (values.size() != 3 && values.size() != 4) {
      throw TrajectoryFileError(name, line, "expected x,y,z or x,y,z,yaw, got " + std::to_string(values.size()) +
                                                " columns");
    }
    out.push_back(waypointFromNumbers(values));
    if (out.back().has_yaw != out.front().has_yaw) {
      throw TrajectoryFileError(name, line, "give yaw on every waypoint or on none");
    }
  }
  if (out.size() < 2) throw TrajectoryFileError(name, line, "need at least 2 waypoints");
  return out;
}

std::vector<Waypoint> readWaypointCsv(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw TrajectoryFileError(path, 0, "cannot open file");
  return parseWaypointCsv(file, path);
}

}  // namespace sdlqr::trajectory
