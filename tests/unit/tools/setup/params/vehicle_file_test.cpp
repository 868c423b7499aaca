// config/quad255.yaml is the declarations printed: same keys, values, units and help, line for line.
// Also the whole-file loader's rules across sections and the sdlqr-params command line.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "sdlqr/params/vehicle_file.hpp"
#include "test_paths.hpp"

#include "config_errors.hpp"

namespace sdlqr::params {
namespace {

std::string shippedFile() {
  std::ifstream in(SDLQR_VEHICLE_FILE);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = sdlqr::test::tempPath(name);
  std::ofstream(path) << text;
  return path;
}

TEST(VehicleFile, TheShippedFileIsThePrintedDeclarations) {
  const std::string shipped = shippedFile();
  EXPECT_EQ(firstDifference(defaultVehicleFileText(), shipped), "")
      << "regenerate it: build/bin/sdlqr-params --defaults > config/quad255.yaml";
  EXPECT_TRUE(shipped == defaultVehicleFileText()) << "the texts differ (see above)";
}

// The comparison above fails on any change a hand edit of the shipped file could make.
TEST(VehicleFile, AChangedValueUnitOrKeyIsFoundWithItsLine) {
  const std::string printed = defaultVehicleFileText();
  const std::string value = replaced(printed, "  mass: 0.255 ", "  mass: 0.3   ");
  const std::string unit = replaced(printed, "# [kg] take-off weight", "# [g] take-off weight");
  const std::string key = replaced(printed, "  c_min: 2.0                          # [m/s^2] thrust lower limit\n", "");
  const std::string extra = printed + "  extra: 1\n";
  for (const std::string& changed : {value, unit, key, extra}) {
    const std::string difference = firstDifference(printed, changed);
    EXPECT_EQ(difference.rfind("line ", 0), 0u) << difference;
  }
  EXPECT_NE(firstDifference(printed, value).find("mass: 0.3"), std::string::npos);
  EXPECT_NE(firstDifference(printed, extra).find("expected the end"), std::string::npos);
}

TEST(VehicleFile, EveryDeclaredKeyIsInThePrintedFileWithItsDefault) {
  const YAML::Node printed = YAML::Load(defaultVehicleFileText());
  for (const auto& [section, declaration] : declarations()) {
    ASSERT_TRUE(printed[section]) << section;
    std::set<std::string> printed_keys;
    std::vector<std::pair<std::string, YAML::Node>> stack{{"", printed[section]}};
    while (!stack.empty()) {
      const auto [prefix, node] = stack.back();
      stack.pop_back();
      for (const auto& entry : node) {
        const std::string key = prefix + entry.first.as<std::string>();
        if (entry.second.IsMap()) {
          stack.push_back({key + ".", entry.second});
        } else {
          printed_keys.insert(key);
          EXPECT_FALSE(entry.second.IsNull()) << key;
        }
      }
    }
    std::set<std::string> declared_keys;
    for (const ParamInfo& info : declaration->params()) {
      if (info.derived) continue;  // printed commented out: it follows from other keys
      declared_keys.insert(info.key);
      const YAML::Node value = YAML::Load(info.default_text);
      if (value.IsScalar()) {
        YAML::Node node;
        node.reset(printed[section]);
        std::stringstream parts(info.key);
        std::string part;
        while (std::getline(parts, part, '.')) {
          const YAML::Node child = node[part];
          node.reset(child);
        }
        EXPECT_EQ(node.Scalar(), value.Scalar()) << section << "." << info.key;
      }
    }
    EXPECT_EQ(printed_keys, declared_keys) << section;
  }
}

TEST(VehicleFile, TheShippedFileLoadsToTheDefaults) {
  const VehicleFile loaded = VehicleFile::load(SDLQR_VEHICLE_FILE);
  std::ostringstream text;
  printSections(text, {}, loaded.sections());
  std::ostringstream defaults;
  printSections(defaults, {}, VehicleFile().sections());
  EXPECT_EQ(text.str(), defaults.str());
}

// config/agile752.yaml (issue 25) loads as the processes read it and is of the racing class the
// issue asks for: thrust-to-weight >= 4, ||omega|| limit >= 8 rad/s, c_max >= 35 m/s^2, and the
// c_max it asks within what its rotors produce.
TEST(VehicleFile, TheAgileVehicleIsOfTheRacingClass) {
  const VehicleFile agile = VehicleFile::load(SDLQR_SOURCE_DIR "/config/agile752.yaml");
  const double weight = agile.vehicle.mass * agile.lqr.gravity;
  const double thrust_to_weight = 4.0 * agile.vehicle.max_rotor_thrust / weight;
  EXPECT_GE(thrust_to_weight, 4.0);
  EXPECT_GE(agile.lqr.omega_max, 8.0);
  EXPECT_GE(agile.lqr.c_max, 35.0);
  EXPECT_LT(agile.lqr.c_max, 4.0 * agile.vehicle.max_rotor_thrust / agile.vehicle.mass);
  std::printf("agile752: thrust-to-weight %.2f, omega_max %.1f rad/s, c_max %.1f m/s^2\n", thrust_to_weight,
              agile.lqr.omega_max, agile.lqr.c_max);
}

TEST(VehicleFile, RulesAcrossSectionsNameTheKey) {
  auto keyOf = [](const std::string& yaml) {
    return testing::keyBlamedBy([&] { VehicleFile::load(writeTemp("cross_section.yaml", yaml)); });
  };
  EXPECT_EQ(keyOf("validation: {max_body_rate: 2.0}\n"), "lowlevel.failsafe.max_rate");
  EXPECT_EQ(keyOf("lowlevel: {idle_thrust: 1.5}\n"), "lowlevel.idle_thrust");
  EXPECT_EQ(keyOf("lqr: {omega_max: 40}\n"), "lqr.omega_max");
  EXPECT_EQ(keyOf("lqr: {c_max: 70}\n"), "lqr.c_max");
  EXPECT_EQ(keyOf("vehicle: {mass: 0.6}\n"), "vehicle.max_rotor_thrust");  // 4 x 1.25 N cannot lift it
  EXPECT_EQ(keyOf("no_such_section: {}\n"), "no_such_section");
  EXPECT_EQ(keyOf("validation: {max_body_rate: 3.0}\n"), "<no error>");  // guards the first case
}

struct CommandRun {
  int exit_code;
  std::string out;
};

CommandRun sdlqrParams(const std::string& arguments) {
  const std::string out_path = sdlqr::test::tempPath("sdlqr_params.out");
  const int status =
      std::system((std::string(SDLQR_BINARY_DIR) + "/bin/sdlqr-params " + arguments + " > " + out_path + " 2>&1").c_str());
  std::ifstream in(out_path);
  std::stringstream text;
  text << in.rdbuf();
  std::remove(out_path.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, text.str()};
}

TEST(SdlqrParams, PrintsTheDefaultsAndComparesAFileWithThem) {
  const CommandRun defaults = sdlqrParams("--defaults");
  EXPECT_EQ(defaults.exit_code, 0);
  EXPECT_EQ(defaults.out, defaultVehicleFileText());
  EXPECT_EQ(sdlqrParams(std::string("--compare-defaults ") + SDLQR_VEHICLE_FILE).exit_code, 0);
  const std::string edited =
      writeTemp("edited.yaml", replaced(defaultVehicleFileText(), "  dt: 0.01 ", "  dt: 0.02 "));
  const CommandRun compared = sdlqrParams("--compare-defaults " + edited);
  EXPECT_EQ(compared.exit_code, 1);
  EXPECT_NE(compared.out.find("dt: 0.02"), std::string::npos) << compared.out;
}

TEST(SdlqrParams, ChecksAFileAsTheProcessesRead) {
  EXPECT_EQ(sdlqrParams(std::string("--check ") + SDLQR_VEHICLE_FILE).exit_code, 0);
  const CommandRun bad = sdlqrParams("--check " + writeTemp("bad.yaml", "lqr: {r_diag: [1, 0, 1, 1]}\n"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(bad.out, "sdlqr-params: config error: lqr.r_diag[1]: must be > 0\n");
  const CommandRun shown = sdlqrParams("--print " + writeTemp("small.yaml", "lqr: {dt: 0.02}\n"));
  EXPECT_EQ(shown.exit_code, 0);
  EXPECT_NE(shown.out.find("  dt: 0.02 "), std::string::npos) << shown.out;
}

}  // namespace
}  // namespace sdlqr::params
