// The executable's contract before it touches the bus: --help, and one-line errors with exit
// code 2 for bad options and bad configuration.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include "executable_run.hpp"

namespace {

using ProcessRun = sdlqr::testing::ExecutableRun;

ProcessRun runProcess(const std::string& args) { return sdlqr::testing::runExecutable("sdlqr-estimator", args); }

std::string writeConfig(const std::string& name, const std::string& text) {
  const std::string path = std::string(SDLQR_BINARY_DIR) + "/tests/unit/estimator/" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(EstimatorCli, HelpExitsZeroAndNamesTheChannels) {
  const ProcessRun run = runProcess("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.output.find("usage: sdlqr-estimator"), std::string::npos);
  EXPECT_NE(run.output.find("--lcm-url"), std::string::npos);
  EXPECT_NE(run.output.find("STATE_EST"), std::string::npos);
}

TEST(EstimatorCli, BadConfigurationIsOneLineNamingTheKeyAndExitTwo) {
  const ProcessRun unknown = runProcess("--config " + writeConfig("unknown_key.yaml", "estimator:\n  histori_length: 0.2\n"));
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.output.find("estimator.histori_length"), std::string::npos) << unknown.output;
  EXPECT_EQ(std::count(unknown.output.begin(), unknown.output.end(), '\n'), 1) << unknown.output;

  const ProcessRun short_history =
      runProcess("--config " + writeConfig("short_history.yaml", "estimator:\n  history_length: 0.05\n"));
  EXPECT_EQ(short_history.exit_code, 2);
  EXPECT_NE(short_history.output.find("estimator.history_length"), std::string::npos) << short_history.output;

  const ProcessRun missing = runProcess("--config /nonexistent/quad.yaml");
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output.find("/nonexistent/quad.yaml"), std::string::npos);
}

TEST(EstimatorCli, UnknownOptionExitsTwo) {
  const ProcessRun run = runProcess("--frobnicate");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.output.find("--frobnicate"), std::string::npos);
}

}  // namespace
