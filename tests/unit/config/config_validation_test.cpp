// Config validation of every process, table-driven over config/quad255.yaml and two scenarios: for each field of
// each section a wrong type, a non-finite and (numbers) a negative value, a list of the wrong
// length, and an unknown key in every section; plus a missing and an unparsable file. Each case
// runs the real executable (in a network namespace without interfaces) and expects exit code 2
// and exactly one line on stderr that names the key.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Which executables read which section (their main's ::load calls).
const std::map<std::string, std::vector<std::string>>& readers() {
  static const std::map<std::string, std::vector<std::string>> table{
      {"vehicle", {"bin/sdlqr-sim", "bin/sdlqr-lowlevel"}},
      {"lqr", {"bin/sdlqr-controller", "bin/sdlqr-gains", "bin/sdlqr-lowlevel", "bin/sdlqr-mission"}},
      {"sim", {"bin/sdlqr-sim"}},
      {"lowlevel", {"bin/sdlqr-lowlevel"}},
      {"trajectory", {"bin/sdlqr-mission"}},
      {"estimator", {"bin/sdlqr-estimator"}},
      {"faults", {"bin/sdlqr-controller", "bin/sdlqr-gains", "bin/sdlqr-lowlevel"}},
      {"controller", {"bin/sdlqr-controller"}},
      {"gains", {"bin/sdlqr-gains"}},
  };
  return table;
}

std::vector<std::string> allExecutables() {
  std::set<std::string> all;
  for (const auto& [section, exes] : readers()) all.insert(exes.begin(), exes.end());
  return {all.begin(), all.end()};
}

// Fields that legitimately take any finite number of either sign, with the reason.
const std::map<std::string, const char*>& signedFields() {
  static const std::map<std::string, const char*> table{
      {"vehicle.yaw_sign", "a sign per rotor: -1 is one of the two valid values"},
      {"sim.initial_position", "a position in the world"},
      {"sim.initial_yaw", "an angle"},
      {"trajectory.height_offset", "a shift of the waypoints' z, either way"},
      {"trajectory.yaw", "an angle"},
  };
  return table;
}

struct Case {
  std::string name;       // gtest-safe
  std::string key;        // what the error must name
  std::string executable; // relative to the build folder
  std::string yaml;       // the whole vehicle file, or empty with `config_path` set
  std::string config_path;
  bool scenario = false;  // the file is a scenario for sdlqr-mission, not a vehicle file
};

std::string joined(const std::vector<std::string>& path) {
  std::string out;
  for (const std::string& part : path) out += (out.empty() ? "" : ".") + part;
  return out;
}

std::string safeName(std::string text) {
  for (char& c : text) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return text;
}

std::string shortName(const std::string& executable) { return executable.substr(executable.rfind('/') + 1); }

YAML::Node nodeAt(YAML::Node root, const std::vector<std::string>& path) {
  YAML::Node node;
  node.reset(root);
  for (const std::string& key : path) {
    YAML::Node next = node[key];
    node.reset(next);
  }
  return node;
}

std::string emit(const YAML::Node& root) {
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

bool isNumber(const YAML::Node& scalar) {
  double value = 0.0;
  return YAML::convert<double>::decode(scalar, value);
}

void collectLeaves(const YAML::Node& node, std::vector<std::string>& path,
                   std::vector<std::vector<std::string>>& leaves, std::vector<std::vector<std::string>>& maps) {
  if (node.IsMap()) {
    maps.push_back(path);
    for (const auto& entry : node) {
      path.push_back(entry.first.as<std::string>());
      collectLeaves(entry.second, path, leaves, maps);
      path.pop_back();
    }
  } else {
    leaves.push_back(path);
  }
}

// The vehicle file plus the sections it leaves to the defaults, so those are tested as well.
YAML::Node baseConfig() {
  YAML::Node root = YAML::LoadFile(SDLQR_VEHICLE_FILE);
  if (!root["controller"]) {
    YAML::Node controller;
    controller["rate_hz"] = 100.0;
    controller["gains_stale_s"] = 0.3;
    controller["gains_fallback_s"] = 1.0;
    controller["takeoff_speed"] = 0.5;
    controller["landing_speed"] = 0.4;
    controller["rejoin_height"] = 0.2;
    controller["tracking"] = "spatial";
    root["controller"] = controller;
  }
  if (!root["gains"]) {
    YAML::Node gains;
    gains["rate_hz"] = 10.0;
    gains["state_timeout_s"] = 0.5;
    root["gains"] = gains;
  }
  return root;
}

// The variant of `root` with the leaf at `path` replaced by `value` (a YAML fragment).
std::string withValue(const YAML::Node& root, const std::vector<std::string>& path, const YAML::Node& value) {
  YAML::Node copy = YAML::Clone(root);
  YAML::Node leaf = nodeAt(copy, path);
  leaf = value;
  return emit(copy);
}

std::vector<Case> buildCases() {
  std::vector<Case> cases;
  const YAML::Node root = baseConfig();
  std::vector<std::vector<std::string>> leaves, maps;
  std::vector<std::string> path;
  collectLeaves(root, path, leaves, maps);

  auto add = [&](const std::string& what, const std::string& key, const std::string& yaml, bool every_reader) {
    const std::string section = key.substr(0, key.find('.'));
    const auto found = readers().find(section);
    const std::vector<std::string> exes = found == readers().end() ? allExecutables() : found->second;
    for (size_t i = 0; i < (every_reader ? exes.size() : 1); ++i) {
      cases.push_back({safeName(key + "_" + what + "_" + shortName(exes[i])), key, exes[i], yaml, ""});
    }
  };

  for (const std::vector<std::string>& leaf_path : leaves) {
    const std::string key = joined(leaf_path);
    const YAML::Node original = nodeAt(YAML::Clone(root), leaf_path);
    add("wrong_type", key, withValue(root, leaf_path, YAML::Load("[not, a, value]")), false);
    if (original.IsSequence()) {
      add("string", key, withValue(root, leaf_path, YAML::Node("not-a-list")), false);
      YAML::Node shorter = YAML::Clone(original);
      YAML::Node cut;
      for (size_t i = 0; i + 1 < shorter.size(); ++i) cut.push_back(shorter[i]);
      add("short_list", key, withValue(root, leaf_path, cut), false);
      YAML::Node with_nan = YAML::Clone(original);
      with_nan[0] = YAML::Load(".nan");
      add("nan_element", key, withValue(root, leaf_path, with_nan), false);
    } else if (isNumber(original)) {
      add("string", key, withValue(root, leaf_path, YAML::Node("not-a-number")), false);
      add("nan", key, withValue(root, leaf_path, YAML::Load(".nan")), false);
      add("inf", key, withValue(root, leaf_path, YAML::Load(".inf")), false);
      if (!signedFields().count(key)) add("negative", key, withValue(root, leaf_path, YAML::Node(-1.0)), false);
    } else {
      add("bad_word", key, withValue(root, leaf_path, YAML::Node("not-a-choice")), false);
    }
  }
  // An unknown key in every section and subsection, seen by every process that reads it.
  for (const std::vector<std::string>& map_path : maps) {
    YAML::Node copy = YAML::Clone(root);
    nodeAt(copy, map_path)["no_such_key"] = 1;
    std::vector<std::string> key_path = map_path;
    key_path.push_back("no_such_key");
    add("unknown_key", joined(key_path), emit(copy), true);
  }
  // One invalid field per section reaches every process that reads the section.
  for (const auto& [section, exes] : readers()) {
    for (const std::vector<std::string>& leaf_path : leaves) {
      if (leaf_path.front() != section || !isNumber(nodeAt(YAML::Clone(root), leaf_path))) continue;
      add("nan_every_reader", joined(leaf_path), withValue(root, leaf_path, YAML::Load(".nan")), true);
      break;
    }
  }
  for (const std::string& exe : allExecutables()) {
    cases.push_back({safeName("missing_file_" + shortName(exe)), "/no/such/dir/vehicle.yaml", exe, "",
                     "/no/such/dir/vehicle.yaml"});
    // The error names the file (its name is the case name).
    cases.push_back({safeName("unparsable_file_" + shortName(exe)), safeName("unparsable_file_" + shortName(exe)) + ".yaml",
                     exe, "vehicle: [1, 2\nlqr: {\n", ""});
  }
  return cases;
}

// Scenario files (sdlqr-mission): every field of the events of every kind, the header and the
// criteria. Paths name sequence elements as the mission does: events[3].trajectory.laps.
const std::set<std::string>& freeTextFields() {
  static const std::set<std::string> fields{"name", "description", "label"};
  return fields;
}

void collectScenarioLeaves(const YAML::Node& node, const std::string& key, std::vector<std::string>& leaves,
                           std::vector<std::string>& maps) {
  if (node.IsMap()) {
    maps.push_back(key);
    for (const auto& entry : node) {
      const std::string name = entry.first.as<std::string>();
      collectScenarioLeaves(entry.second, key.empty() ? name : key + "." + name, leaves, maps);
    }
  } else if (node.IsSequence() && node.size() > 0 && node[0].IsMap()) {
    for (size_t i = 0; i < node.size(); ++i) {
      collectScenarioLeaves(node[i], key + "[" + std::to_string(i) + "]", leaves, maps);
    }
  } else {
    leaves.push_back(key);
  }
}

// The node at a path written as above ("events[3].trajectory").
YAML::Node scenarioNodeAt(YAML::Node root, const std::string& key) {
  YAML::Node node;
  node.reset(root);
  std::string part;
  std::stringstream parts(key);
  while (std::getline(parts, part, '.')) {
    const size_t bracket = part.find('[');
    YAML::Node next = node[part.substr(0, bracket)];
    node.reset(next);
    if (bracket != std::string::npos) {
      YAML::Node element = node[std::stoi(part.substr(bracket + 1))];
      node.reset(element);
    }
  }
  return node;
}

std::vector<Case> buildScenarioCases() {
  std::vector<Case> cases;
  for (const char* file : {"hover_jumps", "minsnap_pulled"}) {
    YAML::Node root = YAML::LoadFile(std::string(SDLQR_SCENARIO_DIR) + "/" + file + ".yaml");
    root["vehicle"] = SDLQR_VEHICLE_FILE;  // the case files are written elsewhere
    std::vector<std::string> leaves, maps;
    collectScenarioLeaves(root, "", leaves, maps);
    auto add = [&](const std::string& what, const std::string& key, const YAML::Node& changed) {
      cases.push_back({safeName(std::string(file) + "_" + key + "_" + what), key, "bin/sdlqr-mission",
                       emit(changed), "", true});
    };
    for (const std::string& key : leaves) {
      const std::string field = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
      if (freeTextFields().count(field) || key == "vehicle") continue;
      YAML::Node wrong = YAML::Clone(root);
      scenarioNodeAt(wrong, key) = YAML::Load("{not: a value}");
      add("wrong_type", key, wrong);
      if (isNumber(scenarioNodeAt(YAML::Clone(root), key))) {
        YAML::Node nan = YAML::Clone(root);
        scenarioNodeAt(nan, key) = YAML::Load(".nan");
        add("nan", key, nan);
      }
    }
    for (const std::string& map_key : maps) {
      // criteria is an open name: number mapping by design (each analysis looks up the names it
      // knows, with a default): an unknown name is not an error there.
      if (map_key == "criteria") continue;
      YAML::Node copy = YAML::Clone(root);
      scenarioNodeAt(copy, map_key)["no_such_key"] = 1;
      const std::string key = map_key.empty() ? "no_such_key" : map_key + ".no_such_key";
      add("unknown_key", key, copy);
    }
  }
  return cases;
}

struct RunResult {
  int exit_code = -1;
  std::string stderr_text;
};

std::string quoted(const std::string& text) { return "'" + text + "'"; }

bool namespacesAvailable() {
  static const bool available = std::system("unshare -n true > /dev/null 2>&1") == 0 ||
                                std::system("unshare -rn true > /dev/null 2>&1") == 0;
  return available;
}

RunResult run(const std::string& executable, const std::string& config_path, bool scenario,
              const std::string& stderr_path) {
  const std::string unshare = std::system("unshare -n true > /dev/null 2>&1") == 0 ? "unshare -n" : "unshare -rn";
  std::string command = "timeout -s KILL 20 " + unshare + " " + quoted(std::string(SDLQR_BUILD_DIR) + "/" + executable);
  if (scenario) {
    command += " " + quoted(config_path);
  } else {
    if (executable == "bin/sdlqr-mission") command += " " + quoted(SDLQR_SCENARIO_FILE);
    command += " --config " + quoted(config_path);
  }
  command += " > /dev/null 2> " + quoted(stderr_path);
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(stderr_path);
  std::stringstream text;
  text << in.rdbuf();
  result.stderr_text = text.str();
  return result;
}

// Runs every case; one gtest failure per wrong case, named by the case. One test per file kind
// (not one per case): the cases share one process start each and ctest lists two tests.
void runAll(const std::vector<Case>& cases) {
  if (!namespacesAvailable()) GTEST_SKIP() << "no network namespaces: not running processes on the host network";
  const fs::path dir = fs::temp_directory_path() / ("sdlqr_config_" + std::to_string(getpid()));
  fs::create_directories(dir);
  std::map<std::string, int> per_executable;
  int passed = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.executable + " " + c.name);
    std::string config_path = c.config_path;
    if (config_path.empty()) {
      config_path = (dir / (c.name + ".yaml")).string();
      std::ofstream(config_path) << c.yaml;
    }
    const RunResult result = run(c.executable, config_path, c.scenario, (dir / (c.name + ".err")).string());
    const std::string program = shortName(c.executable);
    const bool exit_ok = result.exit_code == 2;
    const bool one_line = std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n') == 1;
    const bool named = result.stderr_text.rfind(program + ": ", 0) == 0 && result.stderr_text.find(c.key) != std::string::npos;
    EXPECT_TRUE(exit_ok) << "exit code " << result.exit_code << ": " << result.stderr_text;
    EXPECT_TRUE(one_line) << "expected one line:\n" << result.stderr_text;
    EXPECT_TRUE(named) << "does not name " << c.key << ": " << result.stderr_text;
    if (exit_ok && one_line && named) ++passed;
    ++per_executable[program];
  }
  fs::remove_all(dir);
  std::cout << passed << " of " << cases.size() << " invalid files refused with one line naming the key, exit 2:";
  for (const auto& [program, count] : per_executable) std::cout << " " << program << " " << count;
  std::cout << "\n";
  ::testing::Test::RecordProperty("cases", static_cast<int>(cases.size()));
  ::testing::Test::RecordProperty("passed", passed);
}

TEST(ConfigValidation, EveryInvalidFieldOfTheVehicleFileIsRefusedByEveryReader) { runAll(buildCases()); }

TEST(ConfigValidation, EveryInvalidFieldOfAScenarioIsRefusedByTheMission) { runAll(buildScenarioCases()); }

}  // namespace
