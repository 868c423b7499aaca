// The sdlqr-sim executable: --help exits 0, a bad configuration exits 2 with a one-line error
// naming the key. Neither opens the bus, so no network namespace is needed.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

struct ProcessResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr
};

ProcessResult runSim(const std::string& arguments) {
  const std::string command = std::string(SDLQR_BINARY_DIR) + "/bin/sdlqr-sim " + arguments + " 2>&1";
  ProcessResult run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[512];
  while (fgets(buffer, sizeof(buffer), pipe)) run.output += buffer;
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return run;
}

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

TEST(Executable, UnknownConfigKeyExitsTwoNamingTheKey) {
  const std::string path = writeConfig("sim_bad_key", "sim:\n  vio:\n    latncy_max_s: 0.05\n");
  const ProcessResult run = runSim("--config " + path);
  std::remove(path.c_str());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("sim.vio.latncy_max_s"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << "one line expected: " << run.output;
}

// The scenario's simulated world is read before the bus opens: a bad value exits 2 naming it.
TEST(Executable, BadScenarioSimKeyExitsTwoNamingTheKey) {
  const std::string path = writeConfig("sim_bad_stress", "sim:\n  wind:\n    gust_std: [1, -1, 0]\n");
  const ProcessResult run = runSim("--scenario " + path);
  std::remove(path.c_str());
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("sim.wind.gust_std[1]"), std::string::npos) << run.output;
  EXPECT_EQ(run.output.find('\n'), run.output.size() - 1) << "one line expected: " << run.output;
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
