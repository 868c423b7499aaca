// Comparisons of short flights: the same files bit for bit whatever the thread count, numbers that
// read back exactly, and a speed sweep that finds a failing speed on a range beyond the path
// criteria and none on a slow one.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "sdlqr/batch/results.hpp"
#include "sdlqr/compare/compare_files.hpp"
#include "sdlqr/compare/compare_metrics.hpp"
#include "sdlqr/compare/compare_report.hpp"
#include "sdlqr/tables/csv.hpp"
#include "compare_test_dir.hpp"
#include "../work_folder.hpp"

namespace sdlqr::compare {
namespace {

using ::sdlqr::test::fileText;
using test::kDir;

const std::string kRunWork = ::sdlqr::test::processWorkFolder("compare_run_test");
const auto* const kRemoveWorkFolder = ::sdlqr::test::removeAtExit(kRunWork);

CompareResult runQuietly(const Benchmark& benchmark, int jobs) {
  CompareOptions options;
  options.jobs = jobs;
  options.progress = nullptr;
  return runCompare(benchmark, options);
}

class SmallComparison : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    benchmark_ = new Benchmark(Benchmark::load(kDir + "/small_benchmark.yaml"));
    result_ = new CompareResult(runQuietly(*benchmark_, 1));
    writeCompareFiles(*benchmark_, *result_, kRunWork + "/jobs1");
  }
  static void TearDownTestSuite() {
    delete benchmark_;
    delete result_;
  }
  static Benchmark* benchmark_;
  static CompareResult* result_;
};
Benchmark* SmallComparison::benchmark_ = nullptr;
CompareResult* SmallComparison::result_ = nullptr;

TEST_F(SmallComparison, EveryControllerFliesEveryExperimentAndTheSlowSweepPasses) {
  ASSERT_EQ(result_->flights.size(), 4u);
  const std::vector<std::pair<std::string, std::string>> expected = {
      {"short_hover", "sdlqr"}, {"short_hover", "geometric"}, {"short_circle", "sdlqr"}, {"short_circle", "geometric"}};
  for (size_t i = 0; i < expected.size(); ++i) {
    const ExperimentFlight& f = result_->flights[i];
    EXPECT_EQ(f.experiment, expected[i].first);
    EXPECT_EQ(f.controller, expected[i].second);
    EXPECT_FALSE(f.report.checks.empty());
    EXPECT_GT(f.track.size(), 250u);  // 10.5 s or more at 25 Hz
    EXPECT_EQ(f.path.empty(), f.experiment == "short_hover");
  }
  ASSERT_EQ(result_->sweeps.size(), 2u);
  for (const SweepResult& s : result_->sweeps) {
    ASSERT_EQ(s.flights.size(), 2u) << s.controller;
    for (const SweepFlight& f : s.flights) {
      EXPECT_TRUE(f.pass) << s.controller << " at " << f.speed;
      EXPECT_LT(f.path_error_rms, 0.15);
    }
    EXPECT_TRUE(std::isnan(s.first_failing_speed)) << s.controller;
    EXPECT_EQ(s.highest_passing_speed, 1.0);
  }
  EXPECT_EQ(result_->flown, 4 + 4);
}

TEST_F(SmallComparison, TheSameFilesBitForBitOnTwoThreads) {
  const CompareResult again = runQuietly(*benchmark_, 2);
  writeCompareFiles(*benchmark_, again, kRunWork + "/jobs2");
  for (const std::string file : {"report.md", "flights.csv", "sweep.csv", "tracks/short_hover.csv",
                                 "tracks/short_circle.csv", "tracks/short_circle.path.csv"}) {
    const std::string first = fileText(kRunWork + "/jobs1/" + file);
    EXPECT_GT(first.size(), 100u) << file;
    EXPECT_EQ(first, fileText(kRunWork + "/jobs2/" + file)) << file;
  }
}

TEST_F(SmallComparison, FlightsCsvReadsBackToTheMetricsExactly) {
  std::istringstream in(fileText(kRunWork + "/jobs1/flights.csv"));
  std::vector<std::string> header, cells;
  std::string error;
  ASSERT_TRUE(tables::readCsvRecord(in, &header, &error)) << error;
  const size_t first_metric = 7;
  ASSERT_EQ(header.size(), first_metric + compareMetrics().size());
  for (const ExperimentFlight& f : result_->flights) {
    ASSERT_TRUE(tables::readCsvRecord(in, &cells, &error)) << error;
    EXPECT_EQ(cells[1], f.controller);
    for (size_t m = 0; m < compareMetrics().size(); ++m) {
      double read = 0.0;
      ASSERT_TRUE(tables::parseValue(cells[first_metric + m], read)) << cells[first_metric + m];
      const double value = compareMetrics()[m].of(f.report);
      if (std::isnan(value)) {
        EXPECT_TRUE(std::isnan(read)) << header[first_metric + m];
      } else {
        EXPECT_EQ(read, value) << header[first_metric + m];
      }
    }
  }
}

TEST_F(SmallComparison, TheReportHasEveryTable) {
  const std::string report = fileText(kRunWork + "/jobs1/report.md");
  for (const std::string part : {"## Summary", "## speed_sweep: short_circle", "## short_hover", "## short_circle",
                                 "path_error_rms_max [m]",
                                 "## Where sdlqr is not the best", "| `sdlqr` |", "| `geometric` |",
                                 "jump_settle_time_max [s]", "pull_return_time_max [s]", "| 0.5 m/s |",
                                 // the headline (headline.hpp): per vehicle and law, the fastest speed within the
                                 // criteria, and sdlqr against the others
                                 "## Headline", "| quad255 | `sdlqr` |", "| quad255 | `geometric` |",
                                 "- sdlqr vs `geometric`:"}) {
    EXPECT_NE(report.find(part), std::string::npos) << part;
  }
  // A metric that applies to no flight of the experiment has no column.
  const size_t hover = report.find("## short_hover");
  const std::string hover_table = report.substr(hover, report.find("## short_circle") - hover);
  EXPECT_EQ(hover_table.find("recovery_level_time"), std::string::npos);
  EXPECT_EQ(hover_table.find("path_error_rms_max"), std::string::npos);
  EXPECT_FALSE(std::ifstream(kRunWork + "/jobs1/tracks/short_hover.path.csv").good()) << "no upload, no path file";
}

// The negative: a speed known to be beyond the path criteria (short_circle_tight.yaml: RMS 0.09 m
// at 3.5 m/s for both laws, the limit 0.03 m) fails, where the slow range above passed.
TEST(SpeedSweep, FindsTheFailingSpeedOnARangeBeyondThePathCriteria) {
  Benchmark b = Benchmark::load(kDir + "/small_benchmark.yaml");
  b.experiments.clear();
  b.sweep.scenario_path = kDir + "/short_circle_tight.yaml";
  b.sweep.speeds = {3.5};
  const CompareResult r = runQuietly(b, 2);
  ASSERT_EQ(r.sweeps.size(), 2u);
  for (const SweepResult& s : r.sweeps) {
    ASSERT_EQ(s.flights.size(), 1u) << s.controller << ": the sweep stops at its first failing speed";
    EXPECT_FALSE(s.flights[0].pass);
    EXPECT_EQ(s.first_failing_speed, b.sweep.speeds[0]) << s.controller;
    EXPECT_TRUE(std::isnan(s.highest_passing_speed));
    EXPECT_FALSE(s.flights[0].failed.empty());
  }
  const std::string report = reportMarkdown(b, r);
  EXPECT_NE(report.find("fail**"), std::string::npos);
}

TEST(SpeedSweep, EachSpeedFliesEverySeedAndPassesOnlyWhenEveryOnePasses) {
  Benchmark b = Benchmark::load(kDir + "/small_benchmark.yaml");
  b.experiments.clear();
  b.controllers = {"sdlqr"};
  b.sweep.speeds = {1.0};
  b.sweep.seeds = {5, 6};
  const CompareResult r = runQuietly(b, 2);
  EXPECT_EQ(r.sweep_seeds, (std::vector<long long>{5, 6}));
  ASSERT_EQ(r.sweeps.size(), 1u);
  ASSERT_EQ(r.sweeps[0].flights.size(), 1u);
  const SweepFlight& both = r.sweeps[0].flights[0];
  EXPECT_EQ(both.flights, 2);
  EXPECT_EQ(r.flown, 2);
  // Its errors are the worse seed's.
  const batch::BatchContext context = scenarioContext(b.sweep.scenario_path, b.controllers, -1);
  const SweepFlight five = flySweepSpeed(context, b.sweep.fail_on, "sdlqr", 1.0, {5});
  const SweepFlight six = flySweepSpeed(context, b.sweep.fail_on, "sdlqr", 1.0, {6});
  EXPECT_NE(five.path_error_rms, six.path_error_rms) << "the seeds fly differently";
  EXPECT_EQ(both.path_error_rms, std::max(five.path_error_rms, six.path_error_rms));
  EXPECT_EQ(both.pass, five.pass && six.pass);
  // A seed of the benchmark (--seed) replaces the sweep's.
  b.seed = 9;
  EXPECT_EQ(sweepSeeds(b, context.scenario), std::vector<long long>{9});
}

// A real slow flight's report passes its fail_on checks; the same report with a crash (as after the
// path, in the exit or the landing), or with no fail_on check judged, is no passing speed.
TEST(SpeedSweep, AFlightThatCrashedOrJudgedNoFailOnCheckFailsItsSpeed) {
  const Benchmark b = Benchmark::load(kDir + "/small_benchmark.yaml");
  const batch::BatchContext context = scenarioContext(b.sweep.scenario_path, {"sdlqr"}, -1);
  batch::FlightWorld world{{context.config.vehicle, context.config.sim}, atSpeed(context.scenario, 1.0)};
  analysis::FlightReport report = batch::fly(context, world, "sdlqr").report;
  ASSERT_FALSE(report.crashed);
  ASSERT_TRUE(sweepFlightPasses(report, b.sweep.fail_on));
  analysis::FlightReport crashed = report;
  crashed.crashed = true;
  EXPECT_FALSE(sweepFlightPasses(crashed, b.sweep.fail_on));
  EXPECT_FALSE(sweepFlightPasses(report, {"no_such_criterion"}));
}

TEST(SpeedSweep, ASpeedBeyondTheVehicleIsRefusedForEveryControllerNotFlown) {
  Benchmark b = Benchmark::load(kDir + "/small_benchmark.yaml");
  b.experiments.clear();
  b.sweep.speeds = {0.5, 20.0, 25.0};
  const CompareResult r = runQuietly(b, 1);
  ASSERT_EQ(r.refusals.size(), 3u);
  EXPECT_TRUE(r.refusals[0].empty());
  EXPECT_NE(r.refusals[1].find("beyond the vehicle"), std::string::npos) << r.refusals[1];
  for (const SweepResult& s : r.sweeps) {
    ASSERT_EQ(s.flights.size(), 2u);
    EXPECT_TRUE(s.flights[0].pass);
    EXPECT_FALSE(s.flights[1].feasible);
    EXPECT_TRUE(std::isnan(s.first_failing_speed)) << "the vehicle's limit is no controller's failure";
  }
  EXPECT_EQ(r.flown, 2);  // neither the refused speed nor the one after it
}

}  // namespace
}  // namespace sdlqr::compare
