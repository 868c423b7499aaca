// Config validation of every process. The vehicle-file cases come from the parameter declarations
// (declared_cases.hpp: every declared key with a wrong type, NaN, Inf, values outside its range, a
// short list, ...; an unknown key in every section), the readers of each section from each
// executable's --print-config; plus a missing and an unparsable file, and every field of two
// scenarios. Each case runs the real executable (in a network namespace without interfaces) and
// expects exit code 2 and exactly one line on stderr that names the key.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "prerequisite.hpp"
#include "declared_cases.hpp"
#include "sdlqr/params/vehicle_file.hpp"
#include "test_paths.hpp"

namespace {

namespace fs = std::filesystem;

struct Case {
  std::string name;       // gtest-safe
  std::string key;        // what the error must name
  std::string executable; // relative to the build folder
  std::string yaml;       // the whole vehicle file, or empty with `config_path` set
  std::string config_path;
  bool scenario = false;  // the file is a scenario for sdlqr-mission, not a vehicle file
};

std::string emit(const YAML::Node& root) {
  YAML::Emitter out;
  out << root;
  return std::string(out.c_str()) + "\n";
}

bool isNumber(const YAML::Node& scalar) {
  double value = 0.0;
  return YAML::convert<double>::decode(scalar, value);
}

std::string shortName(const std::string& executable) { return executable.substr(executable.rfind('/') + 1); }

std::vector<std::string> configReaders() {
  std::vector<std::string> out;
  std::stringstream list(SDLQR_CONFIG_READERS);
  std::string exe;
  while (std::getline(list, exe, ',')) out.push_back(exe);
  return out;
}

std::string quoted(const std::string& text) { return "'" + text + "'"; }

// The executable with the positional argument it needs besides the vehicle file (read first).
std::string commandOf(const std::string& executable) {
  std::string command = quoted(std::string(SDLQR_BUILD_DIR) + "/" + executable);
  if (executable == "bin/sdlqr-mission") command += " " + quoted(SDLQR_SCENARIO_FILE);
  if (executable == "bin/sdlqr-replay") command += " " + quoted(std::string(SDLQR_BUILD_DIR) + "/no_such_flight.lcmlog");
  if (executable == "bin/sdlqr-trajectory") command += " minsnap_fast --output /dev/null";
  return command;
}

// What `executable --print-config` prints (the sections it reads, with the built-in defaults).
std::string printedConfig(const std::string& executable) {
  const std::string out_path = sdlqr::test::tempPath("print_config_" + shortName(executable) + ".yaml");
  const int status = std::system(
      (commandOf(executable) + " --config " + quoted(SDLQR_VEHICLE_FILE) + " --print-config > " + quoted(out_path)).c_str());
  EXPECT_EQ(WIFEXITED(status) ? WEXITSTATUS(status) : -1, 0) << executable << " --print-config";
  std::ifstream in(out_path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Which executables read which section: what each says with --print-config.
const std::map<std::string, std::vector<std::string>>& readers() {
  static const std::map<std::string, std::vector<std::string>> table = [] {
    std::map<std::string, std::vector<std::string>> out;
    for (const std::string& exe : configReaders()) {
      const YAML::Node printed = YAML::Load(printedConfig(exe));
      for (const auto& section : printed) out[section.first.as<std::string>()].push_back(exe);
    }
    return out;
  }();
  return table;
}

// The printed blocks ("# help\nname:\n  key: ...") of a vehicle-file text, by section name.
std::map<std::string, std::string> sectionBlocks(const std::string& text) {
  std::map<std::string, std::string> blocks;
  std::stringstream in(text);
  std::string line, block, name;
  auto finish = [&] {
    if (!name.empty()) blocks[name] = block;
    block.clear();
    name.clear();
  };
  while (std::getline(in, line)) {
    if (line.empty()) {
      finish();
      continue;
    }
    block += line + "\n";
    if (name.empty() && !line.empty() && line[0] != '#' && line.back() == ':') name = line.substr(0, line.size() - 1);
  }
  finish();
  return blocks;
}

std::vector<Case> buildCases() {
  std::vector<Case> cases;
  const YAML::Node root = YAML::LoadFile(SDLQR_VEHICLE_FILE);
  auto add = [&](const std::string& name, const std::string& key, const std::string& section, const YAML::Node& file,
                 bool every_reader) {
    const auto found = readers().find(section);
    if (found == readers().end()) {
      ADD_FAILURE() << "no executable reads the declared section " << section << " (--print-config)";
      return;
    }
    const std::vector<std::string>& exes = found->second;
    for (size_t i = 0; i < (every_reader ? exes.size() : 1); ++i) {
      cases.push_back({sdlqr::testing::gtestSafe(name + "_" + shortName(exes[i])), key, exes[i], emit(file), ""});
    }
  };
  for (const auto& [section, declaration] : sdlqr::params::declarations()) {
    bool nan_everywhere = false;
    for (const sdlqr::testing::DeclaredCase& c : sdlqr::testing::declaredCases(section, *declaration)) {
      const bool unknown_key = c.name.size() > 12 && c.name.compare(c.name.size() - 12, 12, "_unknown_key") == 0;
      // An unknown key, and one NaN per section, reach every process that reads the section.
      const bool first_nan = !nan_everywhere && c.value.IsScalar() && c.value.Scalar() == ".nan";
      nan_everywhere = nan_everywhere || first_nan;
      add(c.name, c.key, section, sdlqr::testing::withCase(root, c), unknown_key || first_nan);
    }
  }
  for (const std::string& exe : configReaders()) {
    cases.push_back({sdlqr::testing::gtestSafe("missing_file_" + shortName(exe)), "/no/such/dir/vehicle.yaml", exe, "",
                     "/no/such/dir/vehicle.yaml"});
    // The error names the file (its name is the case name).
    cases.push_back({sdlqr::testing::gtestSafe("unparsable_file_" + shortName(exe)),
                     sdlqr::testing::gtestSafe("unparsable_file_" + shortName(exe)) + ".yaml", exe, "vehicle: [1, 2\nlqr: {\n", ""});
    // An unknown top-level section.
    YAML::Node unknown = YAML::Clone(root);
    unknown["no_such_section"]["key"] = 1;
    cases.push_back({sdlqr::testing::gtestSafe("unknown_section_" + shortName(exe)), "no_such_section", exe, emit(unknown), ""});
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
      cases.push_back({sdlqr::testing::gtestSafe(std::string(file) + "_" + key + "_" + what), key, "bin/sdlqr-mission",
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

// As root a plain network namespace, else one inside a user namespace; empty without either.
// Asked once, not per case.
const std::string& unshareCommand() {
  static const std::string command = std::system("unshare -n true > /dev/null 2>&1") == 0    ? "unshare -n"
                                     : std::system("unshare -rn true > /dev/null 2>&1") == 0 ? "unshare -rn"
                                                                                             : "";
  return command;
}

bool namespacesAvailable() { return !unshareCommand().empty(); }

RunResult run(const std::string& executable, const std::string& config_path, bool scenario,
              const std::string& stderr_path) {
  std::string command = "timeout -s KILL 20 " + unshareCommand() + " ";
  if (scenario) {
    command += quoted(std::string(SDLQR_BUILD_DIR) + "/" + executable) + " " + quoted(config_path);
  } else {
    command += commandOf(executable) + " --config " + quoted(config_path);
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

// Each case's executable run, two at a time (a case is mostly process and namespace set-up: 1,263
// of them took 47 s one at a time); results in the order of the cases.
std::vector<RunResult> runEach(const std::vector<Case>& cases, const fs::path& dir) {
  std::vector<RunResult> results(cases.size());
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t i = next++; i < cases.size(); i = next++) {
      const Case& c = cases[i];
      const std::string file = std::to_string(i) + "_" + c.name;  // names repeat across readers
      std::string config_path = c.config_path;
      if (config_path.empty()) {
        config_path = (dir / (file + ".yaml")).string();
        std::ofstream(config_path) << c.yaml;
      }
      results[i] = run(c.executable, config_path, c.scenario, (dir / (file + ".err")).string());
    }
  };
  unshareCommand();  // decided before the workers start
  std::thread other(worker);
  worker();
  other.join();
  return results;
}

// Runs every case; one gtest failure per wrong case, named by the case. One test per file kind
// (not one per case): the cases share one process start each and ctest lists two tests.
void runAll(const std::vector<Case>& cases) {
  // Never runs the processes on the host network instead.
  SDLQR_REQUIRE_PREREQUISITE(namespacesAvailable(), "network namespaces (unshare -n, as root in CI)");
  const fs::path dir = fs::temp_directory_path() / ("sdlqr_config_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::vector<RunResult> results = runEach(cases, dir);
  std::map<std::string, int> per_executable;
  int passed = 0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const RunResult& result = results[i];
    SCOPED_TRACE(c.executable + " " + c.name);
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

// --print-config shows the sections a process reads exactly as the shipped file prints them: one
// declaration behind both.
TEST(ConfigValidation, EveryProcessPrintsItsSectionsAsTheVehicleFileDoes) {
  const std::map<std::string, std::string> shipped = sectionBlocks(sdlqr::params::defaultVehicleFileText());
  for (const std::string& exe : configReaders()) {
    const std::map<std::string, std::string> printed = sectionBlocks(printedConfig(exe));
    EXPECT_FALSE(printed.empty()) << exe << " --print-config printed no section";
    for (const auto& [section, block] : printed) {
      // A process reading part of a section (the mission: controller.guard) prints that part.
      const std::string top = section.substr(0, section.find('.'));
      ASSERT_TRUE(shipped.count(top)) << exe << " prints an undeclared section " << section;
      if (top == section) {
        EXPECT_EQ(block, shipped.at(section)) << exe << " --print-config, section " << section;
      }
    }
  }
  // Every declared section has a reader.
  for (const auto& [section, declaration] : sdlqr::params::declarations()) {
    EXPECT_TRUE(readers().count(section)) << "no executable reads " << section;
  }
}

TEST(ConfigValidation, EveryInvalidFieldOfAScenarioIsRefusedByTheMission) { runAll(buildScenarioCases()); }

}  // namespace
