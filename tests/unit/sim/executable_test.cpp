// The sdlqr-sim executable: --help exits 0, a bad configuration exits 2 with a one-line error
// naming the key. Neither opens the bus, so no network namespace is needed.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "executable_run.hpp"

namespace {

using ProcessResult = sdlqr::testing::ExecutableRun;

ProcessResult runSim(const std::string& arguments) { return sdlqr::testing::runExecutable("sdlqr-sim", arguments); }

std::string writeConfig(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name + "_" + std::to_string(getpid()) + ".yaml";
  std::ofstream(path) << text;
  return path;
}

TEST(Executable, HelpPrintsUsageAndExitsZero) {
  const ProcessResult run = runSim("--help");
  EXPECT_EQ(run.exit_code, 0);
  for (const char* option : {"--config", "--lcm-url", "--vehicle", "--rate", "--seed", "--duration", "--scenario"}) {
    EXPECT_NE(run.output.find(option), std::string::npos) << option;
  }
}

// sdlqr-sim given a file (named after `name`) holding `yaml` with `option`: exit code 2 and one
// line naming `key`.
void expectOneLineNamingTheKey(const std::string& option, const std::string& name, const std::string& yaml,
                               const std::string& key) {
  const std::string path = writeConfig(name, yaml);
  const ProcessResult run = runSim(option + " " + path);
  std::remove(path.c_str());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find(key), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << "one line expected: " << run.output;
}

TEST(Executable, UnknownConfigKeyExitsTwoNamingTheKey) {
  expectOneLineNamingTheKey("--config", "sim_bad_key", "sim:\n  vio:\n    latncy_max_s: 0.05\n", "sim.vio.latncy_max_s");
}

// The scenario's simulated world is read before the bus opens: a bad value exits 2 naming it.
TEST(Executable, BadScenarioSimKeyExitsTwoNamingTheKey) {
  expectOneLineNamingTheKey("--scenario", "sim_bad_stress", "sim:\n  wind:\n    gust_std: [1, -1, 0]\n",
                            "sim.wind.gust_std[1]");
}

TEST(Executable, BadValuesAndOptionsExitTwo) {
  const std::string path = writeConfig("sim_bad_value", "vehicle:\n  mass: -1\n");
  EXPECT_EQ(runSim("--config " + path).exit_code, 2);
  std::remove(path.c_str());
  EXPECT_EQ(runSim("--config /nonexistent/quad.yaml").exit_code, 2);
  EXPECT_EQ(runSim("--rate 0").exit_code, 2);
  EXPECT_EQ(runSim("--rate fast").exit_code, 2);
  EXPECT_EQ(runSim("--duration -1").exit_code, 2);
  EXPECT_EQ(runSim("--seed -5").exit_code, 2);
}

}  // namespace
