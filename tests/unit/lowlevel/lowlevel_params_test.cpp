// The `lowlevel:` section: the repository's vehicle file loads, and every bad value or unknown
// key is reported with its full key path.

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/lowlevel_params.hpp"

#include "config_errors.hpp"
#include "executable_run.hpp"

namespace sdlqr::lowlevel {
namespace {

LowlevelParams loadText(const std::string& yaml) {
  return LowlevelParams::load(ConfigReader(YAML::Load(yaml), "").child("lowlevel"));
}

TEST(LowlevelParams, DefaultsAreValid) {
  const LowlevelParams params;
  EXPECT_TRUE(params.valid()) << params.invalidReason();
  EXPECT_EQ(params.invalidReasonFor(VehicleParams(), 9.81), "");
}

TEST(LowlevelParams, RepositoryVehicleFileLoadsItsSection) {
  const ConfigReader root(loadYamlFile(std::string(SDLQR_SOURCE_DIR) + "/config/quad255.yaml"), "");
  ASSERT_TRUE(root.has("lowlevel"));
  const LowlevelParams params = LowlevelParams::load(root.child("lowlevel"));
  EXPECT_TRUE(params.valid());
  EXPECT_EQ(params.invalidReasonFor(VehicleParams::load(root.child("vehicle")), 9.81), "");
  // The file spells out the values the code defaults to; a drift between them is a mistake.
  const LowlevelParams defaults;
  EXPECT_EQ(params.rate_control.p, defaults.rate_control.p);
  EXPECT_EQ(params.rate_control.i, defaults.rate_control.i);
  EXPECT_EQ(params.rate_control.d, defaults.rate_control.d);
  EXPECT_EQ(params.failsafe.descent_rate, defaults.failsafe.descent_rate);
  EXPECT_EQ(params.attitude_filter.bias_time_constant, defaults.attitude_filter.bias_time_constant);
  EXPECT_EQ(params.rate_cmd_timeout, defaults.rate_cmd_timeout);
}

TEST(LowlevelParams, ValuesAreRead) {
  const LowlevelParams params = loadText(
      "lowlevel:\n  rate_cmd_timeout: 0.2\n  failsafe:\n    descent_rate: 0.8\n"
      "  rate_control:\n    p: [100, 110, 10]\n");
  EXPECT_EQ(params.rate_cmd_timeout, 0.2);
  EXPECT_EQ(params.failsafe.descent_rate, 0.8);
  EXPECT_EQ(params.rate_control.p, Vec3(100, 110, 10));
}

TEST(LowlevelParams, ErrorsNameTheFullKey) {
  testing::expectKeysBlamed(loadText, {
      {"lowlevel:\n  idle_thrust: -1\n", "lowlevel.idle_thrust"},
      {"lowlevel:\n  bogus: 1\n", "lowlevel.bogus"},
      {"lowlevel:\n  failsafe:\n    descnt_rate: 1\n", "lowlevel.failsafe.descnt_rate"},
      {"lowlevel:\n  rate_control:\n    p: [1, -2, 3]\n", "lowlevel.rate_control.p[1]"},
      {"lowlevel:\n  rate_control:\n    p: [1, 2]\n", "lowlevel.rate_control.p"},
      {"lowlevel:\n  dt_min: 0.5\n", "lowlevel.dt_min"},
      {"lowlevel:\n  failsafe:\n    impact_rest_time: 1.0\n", "lowlevel.failsafe.impact_rest_time"},
      {"lowlevel:\n  ground_detector:\n    landed_thrust_ratio: 1.2\n", "lowlevel.ground_detector.landed_thrust_ratio"},
      {"lowlevel:\n  input_limits:\n    max_gyro: .nan\n", "lowlevel.input_limits.max_gyro"},
  });
}

// The RATE_CMD body-rate bound is the stack's one (validation.max_body_rate), not a lowlevel key.
TEST(LowlevelParams, TheBodyRateBoundIsNotALowlevelKey) {
  try {
    loadText("lowlevel:\n  input_limits:\n    max_body_rate: 20\n");
    ADD_FAILURE() << "lowlevel.input_limits.max_body_rate was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "lowlevel.input_limits.max_body_rate: unknown key");
  }
}

TEST(LowlevelParams, TheFailsafeMustStayWithinTheBodyRateBound) {
  LowlevelParams params;
  ValidationLimits limits;
  EXPECT_EQ(params.invalidReasonFor(limits), "");
  limits.max_body_rate = params.failsafe.max_rate - 0.1;
  EXPECT_EQ(params.invalidReasonFor(limits).rfind("failsafe.max_rate:", 0), 0u);
}

TEST(LowlevelParams, IdleThrustMustSuitTheAirframe) {
  LowlevelParams params;
  params.idle_thrust = 0.5;  // 4 x 0.5 N would nearly lift the 255 g vehicle
  EXPECT_EQ(params.invalidReasonFor(VehicleParams(), 9.81).rfind("idle_thrust:", 0), 0u);
}

int runExecutable(const std::string& arguments) {
  return testing::runExecutable("sdlqr-lowlevel", arguments).exit_code;
}

TEST(LowlevelExecutable, HelpExitsZeroAndBadConfigExitsTwo) {
  EXPECT_EQ(runExecutable("--help"), 0);
  EXPECT_EQ(runExecutable("--no-such-option"), 2);
  const std::string path = std::string(SDLQR_BINARY_DIR) + "/lowlevel_bad_config.yaml";
  std::ofstream(path) << "lowlevel:\n  failsafe:\n    descent_rate: -1\n";
  EXPECT_EQ(runExecutable("--config " + path), 2);
  std::ofstream(path) << "lowlevel:\n  idle_thrust: 1.0\n";
  EXPECT_EQ(runExecutable("--config " + path), 2);
  EXPECT_EQ(runExecutable("--config /nonexistent/vehicle.yaml"), 2);
  std::remove(path.c_str());
}

}  // namespace
}  // namespace sdlqr::lowlevel
