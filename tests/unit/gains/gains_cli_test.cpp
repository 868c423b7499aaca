// sdlqr-gains --once: its parsing and JSON library, and the built executable itself (found via
// SDLQR_BINARY_DIR): the JSON parses strictly, its K equals the library's K digit for digit, and
// every bad input exits with code 2 and one line on stderr.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/gains/gains_cli.hpp"
#include "test_paths.hpp"

namespace sdlqr {
namespace {

// The output is read with nlohmann-json, which rejects anything that is not RFC 8259 JSON.
using Json = nlohmann::json;

Json parseJson(const std::string& text) { return Json::parse(text); }

// --- the executable ---
struct RunResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

RunResult runGains(const std::string& arguments) {
  const std::string base = sdlqr::test::tempPath("gains");
  const std::string command = std::string(SDLQR_BINARY_DIR) + "/bin/sdlqr-gains " + arguments + " >" + base +
                              ".out 2>" + base + ".err";
  const int status = std::system(command.c_str());
  RunResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = readFile(base + ".out");
  result.err = readFile(base + ".err");
  std::remove((base + ".out").c_str());
  std::remove((base + ".err").c_str());
  return result;
}

GainMatrix gainOf(const Json& json) {
  const Json& K = json.at("K");
  EXPECT_EQ(K.size(), 4u);
  GainMatrix gain;
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(K.at(i).size(), 10u);
    for (int j = 0; j < 10; ++j) gain(i, j) = K.at(i).at(j).get<double>();
  }
  return gain;
}

const char* kTiltedState = "1,-2,3,0.8660254037844387,0.5,0,0,4,0,-1";
const char* kFastInput = "3,-2,1,15";

TEST(GainsOnce, PrintsOneJsonObjectWhoseKEqualsTheLibraryDigitForDigit) {
  const RunResult run = runGains(std::string("--once --state ") + kTiltedState + " --input " + kFastInput);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(run.err, "");
  EXPECT_EQ(std::count(run.out.begin(), run.out.end(), '\n'), 1) << "one line of output";
  const Json json = parseJson(run.out);
  EXPECT_EQ(json.at("status").get<std::string>(), "ok");
  EXPECT_EQ(json.at("method").get<std::string>(), "tangent");
  EXPECT_EQ(json.at("dt").get<double>(), 0.01);
  EXPECT_GT(json.at("iterations").get<double>(), 0.0);
  EXPECT_GT(json.at("solve_us").get<double>(), 0.0);
  EXPECT_LT(json.at("residual").get<double>(), 1e-9);
  ASSERT_EQ(json.at("x_lin").size(), 10u);
  ASSERT_EQ(json.at("u_lin").size(), 4u);

  const State x = gains::parseStateList(kTiltedState, "--state");
  const Input u = gains::parseInputList(kFastInput, "--input");
  const LqrResult library = solveLqr(x, u, LqrParams());
  ASSERT_EQ(library.status, SolveStatus::kOk);
  const GainMatrix printed = gainOf(json);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 10; ++j) EXPECT_EQ(printed(i, j), library.K(i, j)) << i << "," << j;
  }
  for (int i = 0; i < 10; ++i) EXPECT_EQ(json.at("x_lin").at(i).get<double>(), x[i]);  // already unit
  std::cout << "solve_us reported by the executable: " << json.at("solve_us").get<double>() << "\n";
}

TEST(GainsOnce, IterativeMethodAndConfigWeightsAreUsed) {
  const std::string config = sdlqr::test::tempPath("gains_test_config.yaml");
  {
    std::ofstream out(config);
    out << "lqr:\n  r_diag: [2, 4, 4, 0.2]\n  dt: 0.02\n  tolerance: 1.0e-11\n";
  }
  const RunResult run = runGains(std::string("--once --state 0,0,1,1,0,0,0,0,0,0 --input 0,0,0,9.81 --config ") +
                                 config + " --method iterative");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json json = parseJson(run.out);
  EXPECT_EQ(json.at("method").get<std::string>(), "iterative");
  EXPECT_EQ(json.at("dt").get<double>(), 0.02);
  LqrParams params;
  params.r_diag << 2, 4, 4, 0.2;
  params.dt = 0.02;
  params.tolerance = 1e-11;
  params.method = LqrMethod::kIterative;
  const LqrResult library = solveLqr(gains::parseStateList("0,0,1,1,0,0,0,0,0,0", "s"),
                                     gains::parseInputList("0,0,0,9.81", "u"), params);
  ASSERT_EQ(library.status, SolveStatus::kOk);
  EXPECT_EQ(gainOf(json), library.K);
  EXPECT_EQ(json.at("iterations").get<double>(), library.iterations);
  std::remove(config.c_str());
}

TEST(GainsOnce, NonUnitQuaternionIsReportedNormalized) {
  const RunResult run = runGains("--once --state 0,0,0,2,0,0,0,0,0,0 --input 0,0,0,9.81");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Json json = parseJson(run.out);
  EXPECT_EQ(json.at("x_lin").at(3).get<double>(), 1.0);
}

TEST(GainsOnce, BadInputExitsWithCodeTwoAndOneLine) {
  const std::string config = sdlqr::test::tempPath("gains_bad_r.yaml");
  {
    std::ofstream out(config);
    out << "lqr:\n  r_diag: [1, 5, 0, 0.1]\n";
  }
  const std::string good_input = " --input 0,0,0,9.81";
  const std::string good_state = " --state 0,0,0,1,0,0,0,0,0,0";
  const std::vector<std::string> cases = {
      "--once --state 0,0,0,1,0,0,0,0,0" + good_input,          // 9 numbers
      "--once --state 0,0,0,1,0,0,0,0,0,0,0" + good_input,      // 11 numbers
      "--once --state 0,0,0,1,0,nan,0,0,0,0" + good_input,      // NaN
      "--once --state 0,0,0,1,0,inf,0,0,0,0" + good_input,      // Inf
      "--once --state 0,0,0,1,0,abc,0,0,0,0" + good_input,      // not a number
      "--once --state 0,0,0,1,,0,0,0,0,0" + good_input,         // empty item
      "--once --state 0,0,0,0,0,0,0,0,0,0" + good_input,        // zero quaternion
      "--once" + good_state + " --input 0,0,9.81",              // 3 inputs
      "--once" + good_state + " --input 0,0,0,1e999",           // overflow
      "--once" + good_state + good_input + " --config " + config,  // R not positive definite
      "--once" + good_state + good_input + " --config /nonexistent/quad.yaml",
      "--once" + good_state + good_input + " --method newton",  // unknown method
      "--once" + good_state,                                    // no input
      "--once" + good_state + good_input + " --bogus",          // unknown option
      good_state.substr(1) + good_input,                        // a point without --once
  };
  for (const std::string& arguments : cases) {
    const RunResult run = runGains(arguments);
    EXPECT_EQ(run.exit_code, 2) << arguments << "\nstdout: " << run.out << "\nstderr: " << run.err;
    EXPECT_EQ(run.out, "") << arguments;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << arguments << ": " << run.err;
    EXPECT_EQ(run.err.rfind("sdlqr-gains: ", 0), 0u) << run.err;
  }
  std::remove(config.c_str());
}

TEST(GainsOnce, HelpExitsZero) {
  const RunResult run = runGains("--help");
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("--once"), std::string::npos);
}

// --- the library behind it ---
TEST(GainsCli, ParsesListsAndRejectsBadOnes) {
  const State x = gains::parseStateList("1,2,3,1,0,0,0,-4,5e-1,6", "--state");
  EXPECT_EQ(x[0], 1.0);
  EXPECT_EQ(x[8], 0.5);
  EXPECT_THROW(gains::parseStateList("1,2,3", "--state"), std::invalid_argument);
  EXPECT_THROW(gains::parseStateList("0,0,0,0,0,0,0,0,0,0", "--state"), std::invalid_argument);
  EXPECT_THROW(gains::parseInputList("1,2,3,x", "--input"), std::invalid_argument);
  EXPECT_THROW(gains::parseInputList("1,2,3,4 ", "--input"), std::invalid_argument);
  try {
    gains::parseInputList("1,2", "--input");
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--input: ", 0), 0u) << e.what();
  }
}

TEST(GainsCli, JsonOfAFailedSolveUsesNullForNonFiniteAndNamesTheReason) {
  LqrResult failed;
  failed.status = SolveStatus::kNotConverged;
  failed.reason = "did not converge";
  failed.residual = std::numeric_limits<double>::quiet_NaN();
  const std::string text = gains::formatGainsJson(State::Zero(), Input::Zero(), LqrParams(), failed, 1.5);
  const Json json = parseJson(text);
  EXPECT_EQ(json.at("status").get<std::string>(), "not_converged");
  EXPECT_EQ(json.at("reason").get<std::string>(), "did not converge");
  EXPECT_TRUE(json.at("residual").is_null());
}

TEST(GainsCli, SeventeenDigitsRoundTrip) {
  LqrResult result;
  result.status = SolveStatus::kOk;
  result.K(2, 7) = 0.1 + 0.2;  // 0.30000000000000004
  result.K(0, 0) = -1.0 / 3.0;
  const Json json = parseJson(gains::formatGainsJson(State::Zero(), Input::Zero(), LqrParams(), result, 0.0));
  EXPECT_EQ(gainOf(json), result.K);
}

}  // namespace
}  // namespace sdlqr
