// Benchmark files: what loads, and every bad key refused with one error naming it.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdlib>
#include <fstream>

#include "sdlqr/batch/results.hpp"
#include "sdlqr/compare/benchmark.hpp"
#include "compare_test_dir.hpp"

namespace sdlqr::compare {
namespace {

using test::kDir;

const std::string kBenchmarkWork = SDLQR_BINARY_DIR "/compare_benchmark_test/" + std::to_string(::getpid());

// A benchmark file of `text` (scenarios named by absolute path or by name).
std::string benchmarkFile(const std::string& text) {
  batch::makeDirectories(kBenchmarkWork);
  static int count = 0;
  const std::string path = kBenchmarkWork + "/benchmark" + std::to_string(count++) + ".yaml";
  std::ofstream(path) << text;
  return path;
}

std::string sweepOf(const std::string& speeds, const std::string& fail_on = "[path_error_rms, path_error_max]") {
  return "speed_sweep: {scenario: " + kDir + "/short_circle.yaml, speeds: " + speeds + ", fail_on: " + fail_on + "}\n";
}

// The key of the ConfigError loading `text` throws ("" when it loads).
std::string errorKey(const std::string& text) {
  try {
    Benchmark::load(benchmarkFile(text));
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line: " << e.what();
    return e.key();
  }
  return "";
}

TEST(Benchmark, TheShippedBenchmarkLoadsEveryLawEveryExperimentAndTheSweep) {
  const Benchmark b = Benchmark::load(SDLQR_SOURCE_DIR "/config/compare/benchmark.yaml");
  EXPECT_EQ(b.controllers, batch::knownControllers());
  std::vector<std::string> names;
  for (const Experiment& e : b.experiments) names.push_back(e.name);
  const std::vector<std::string> expected = {"hover_jumps", "minsnap_fast", "ellipse_infeasible", "minsnap_pulled",
                                             "minsnap_pulled_temporal", "mass_plus20", "hover_jumps_mass_plus20",
                                             "payload_drop", "wind_gusts", "recover_60", "recover_120", "recover_180",
                                             "throw"};
  EXPECT_EQ(names, expected);
  ASSERT_TRUE(b.has_sweep);
  EXPECT_EQ(b.sweep.fail_on, (std::vector<std::string>{"path_error_rms", "path_error_max"}));
  EXPECT_EQ(b.sweep.seeds, (std::vector<long long>{21, 1, 2}));
  EXPECT_EQ(b.seed, -1);
}

TEST(Benchmark, TheSmallBenchmarkLoads) {
  const Benchmark b = Benchmark::load(kDir + "/small_benchmark.yaml");
  EXPECT_EQ(b.controllers, (std::vector<std::string>{"sdlqr", "geometric"}));
  ASSERT_EQ(b.experiments.size(), 2u);
  EXPECT_EQ(b.experiments[0].name, "short_hover");
  EXPECT_EQ(b.experiments[1].name, "short_circle");
  EXPECT_EQ(b.sweep.speeds, (std::vector<double>{0.5, 1.0}));
}

TEST(Benchmark, BadKeysAreRefusedNamingTheKey) {
  EXPECT_EQ(errorKey("controllers: [sdlqr, pid]\nexperiments: [hover_jumps]\n"), "controllers[1]");
  EXPECT_EQ(errorKey("controllers: [sdlqr, sdlqr]\nexperiments: [hover_jumps]\n"), "controllers[1]");
  EXPECT_EQ(errorKey("experiment: [hover_jumps]\n"), "experiment");
  EXPECT_EQ(errorKey("controllers: [sdlqr]\n"), "experiments");
  EXPECT_EQ(errorKey("experiments: [hover_jumps, no_such_scenario]\n"), "experiments[1]");
  EXPECT_EQ(errorKey("experiments: [hover_jumps, hover_jumps]\n"), "experiments[1]");
  EXPECT_EQ(errorKey("experiments: [hover_jumps]\nseed: -3\n"), "seed");
  EXPECT_EQ(errorKey("experiments: [hover_jumps]\nseed: seven\n"), "seed");
  EXPECT_EQ(errorKey(sweepOf("[1.0, 1.0]")), "speed_sweep.speeds[1]");
  EXPECT_EQ(errorKey(sweepOf("[0.0]")), "speed_sweep.speeds[0]");
  EXPECT_EQ(errorKey(sweepOf("[1.0, fast]")), "speed_sweep.speeds[1]");
  EXPECT_EQ(errorKey(sweepOf("[1.0]", "[max_tilt_deg]")), "speed_sweep.fail_on[0]");
  EXPECT_EQ(errorKey(sweepOf("[1.0]", "[skipped_samples_max]")), "speed_sweep.fail_on[0]");  // no limit set
  EXPECT_EQ(errorKey("speed_sweep: {scenario: hover_jumps, speeds: [1.0], fail_on: [path_error_rms]}\n"),
            "speed_sweep.scenario");  // nothing whose speed the sweep could set
  EXPECT_EQ(errorKey("speed_sweep: {scenario: " + kDir + "/short_circle.yaml, speeds: [1.0]}\n"), "speed_sweep.fail_on");
  EXPECT_EQ(errorKey("speed_sweep: {scenario: " + kDir + "/short_circle.yaml, speed: [1.0], fail_on: [path_error_rms]}\n"),
            "speed_sweep.speed");
  const std::string circle = kDir + "/short_circle.yaml";
  EXPECT_EQ(errorKey("speed_sweep: {scenario: " + circle + ", speeds: [1.0], fail_on: [path_error_rms], seeds: [1, -2]}\n"),
            "speed_sweep.seeds[1]");
  EXPECT_EQ(errorKey("speed_sweep: {scenario: " + circle + ", speeds: [1.0], fail_on: [path_error_rms], seeds: [4, 4]}\n"),
            "speed_sweep.seeds[1]");
  EXPECT_EQ(errorKey("speed_sweep: {scenario: " + circle + ", speeds: [1.0], fail_on: [path_error_rms], seeds: []}\n"),
            "speed_sweep.seeds");
  EXPECT_EQ(errorKey(sweepOf("[1.0]")), "");
}

TEST(Benchmark, OptionsSelectControllersAndScenariosNamingABadOne) {
  Benchmark b = Benchmark::load(kDir + "/small_benchmark.yaml");
  selectControllers(b, "geometric");
  EXPECT_EQ(b.controllers, std::vector<std::string>{"geometric"});
  try {
    selectControllers(b, "sdlqr,pid");
    FAIL() << "pid accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "--controllers[1]");
  }
  selectScenarios(b, std::string(kSweepName));
  EXPECT_TRUE(b.experiments.empty());
  EXPECT_TRUE(b.has_sweep);
  b = Benchmark::load(kDir + "/small_benchmark.yaml");
  selectScenarios(b, "short_hover");
  EXPECT_EQ(b.experiments.size(), 1u);
  EXPECT_FALSE(b.has_sweep);
  try {
    selectScenarios(b, "short_hover,hover_jump");
    FAIL() << "hover_jump accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "--scenarios[1]");
  }
}

}  // namespace
}  // namespace sdlqr::compare
