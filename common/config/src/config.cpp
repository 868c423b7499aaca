#include "sdlqr/config/config.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace sdlqr {

YAML::Node loadYamlFile(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw ConfigError(path, "cannot open file");
  try {
    YAML::Node root = YAML::Load(file);
    if (root.IsNull()) return YAML::Node(YAML::NodeType::Map);
    if (!root.IsMap()) throw ConfigError(path, "top level must be a mapping");
    return root;
  } catch (const YAML::Exception& e) {
    std::ostringstream msg;
    msg << "YAML syntax error at line " << e.mark.line + 1 << ", column " << e.mark.column + 1 << ": " << e.msg;
    throw ConfigError(path, msg.str());
  }
}

const std::vector<std::string>& vehicleFileSections() {
  static const std::vector<std::string> sections{"vehicle",    "lqr",      "sim",        "estimator", "controller",
                                                 "gains",      "lowlevel", "trajectory", "faults",    "validation",
                                                 "px4",        "px4_emulator"};
  return sections;
}

ConfigReader loadVehicleConfig(const std::string& path) {
  if (path.empty()) return ConfigReader(YAML::Node(YAML::NodeType::Map), "");
  ConfigReader root(loadYamlFile(path), "");
  root.allowOnly(vehicleFileSections());
  return root;
}

ConfigReader::ConfigReader(YAML::Node node, std::string path) : node_(std::move(node)), path_(std::move(path)) {
  if (node_ && !node_.IsNull() && !node_.IsMap()) throw ConfigError(path_.empty() ? "<root>" : path_, "must be a mapping");
}

bool ConfigReader::has(const std::string& key) const {
  return node_ && node_.IsMap() && node_[key] && !node_[key].IsNull();
}

ConfigReader ConfigReader::child(const std::string& key) const {
  if (!has(key)) return ConfigReader(YAML::Node(), keyPath(key));
  return ConfigReader(node_[key], keyPath(key));
}

void ConfigReader::allowOnly(std::initializer_list<const char*> allowed) const {
  allowOnly(std::vector<std::string>(allowed.begin(), allowed.end()));
}

namespace {

// Edits (insert, delete, substitute) that turn `a` into `b`.
size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// "unknown key (did you mean 'q_diag'?)" for a near miss, else "unknown key".
std::string unknownKeyReason(const std::string& key, const std::vector<std::string>& allowed) {
  const std::string* nearest = nullptr;
  size_t best = 3;  // more than two edits away is not a typo of it
  for (const std::string& name : allowed) {
    const size_t distance = editDistance(key, name);
    if (distance < best) {
      best = distance;
      nearest = &name;
    }
  }
  return nearest ? "unknown key (did you mean '" + *nearest + "'?)" : "unknown key";
}

}  // namespace

void ConfigReader::allowOnly(const std::vector<std::string>& allowed) const {
  if (!node_ || !node_.IsMap()) return;
  for (const auto& entry : node_) {
    if (!entry.first.IsScalar()) throw ConfigError(keyPath("<key>"), "a key must be a plain word");
    const std::string key = entry.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
      throw ConfigError(keyPath(key), unknownKeyReason(key, allowed));
    }
  }
}

void throwIfInvalid(const ConfigReader& reader, const std::string& reason) {
  if (reason.empty()) return;
  const auto colon = reason.find(": ");
  if (colon == std::string::npos) throw ConfigError(reader.path(), reason);
  throw ConfigError(reader.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
}

namespace {

double toFiniteDouble(const YAML::Node& node, const std::string& key) {
  if (!node.IsScalar()) throw ConfigError(key, "expected a number");
  double value = 0.0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    throw ConfigError(key, "expected a number, got '" + node.Scalar() + "'");
  }
  if (!std::isfinite(value)) throw ConfigError(key, "must be finite");
  return value;
}

// A scalar read as T; anything else (a list, a map, a text that is no T) is `expected` at `key`.
template <class T>
T scalarAs(const YAML::Node& node, const std::string& key, const char* expected) {
  try {
    if (!node.IsScalar()) throw YAML::Exception(YAML::Mark::null_mark(), "");
    return node.as<T>();
  } catch (const YAML::Exception&) {
    throw ConfigError(key, expected);
  }
}

}  // namespace

void ConfigReader::read(const std::string& key, double& out) const {
  if (!has(key)) return;
  out = toFiniteDouble(node_[key], keyPath(key));
}

void ConfigReader::read(const std::string& key, int& out) const {
  if (has(key)) out = scalarAs<int>(node_[key], keyPath(key), "expected an integer");
}

void ConfigReader::read(const std::string& key, long long& out) const {
  if (has(key)) out = scalarAs<long long>(node_[key], keyPath(key), "expected an integer");
}

void ConfigReader::read(const std::string& key, bool& out) const {
  if (has(key)) out = scalarAs<bool>(node_[key], keyPath(key), "expected true or false");
}

void ConfigReader::read(const std::string& key, std::string& out) const {
  if (!has(key)) return;
  const YAML::Node node = node_[key];
  if (!node.IsScalar()) throw ConfigError(keyPath(key), "expected a string");
  out = node.Scalar();
}

void ConfigReader::readVector(const std::string& key, double* out, int size) const {
  if (!has(key)) return;
  const YAML::Node node = node_[key];
  const std::string name = keyPath(key);
  if (!node.IsSequence()) throw ConfigError(name, "expected a list of " + std::to_string(size) + " numbers");
  if (static_cast<int>(node.size()) != size) {
    throw ConfigError(name, "expected " + std::to_string(size) + " numbers, got " + std::to_string(node.size()));
  }
  for (int i = 0; i < size; ++i) out[i] = toFiniteDouble(node[i], name + "[" + std::to_string(i) + "]");
}

}  // namespace sdlqr
