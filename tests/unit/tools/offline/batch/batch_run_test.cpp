// Whole batches of short flights: the same rows whatever --jobs, a killed run resumed without
// flying a finished flight again, shards merged into the single run's rows, a re-flown flight
// reproducing its row from its files, and a known-bad plant failing where a known-good one passes.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <set>
#include <sstream>
#include <thread>

#include "sdlqr/batch/runner.hpp"
#include "sdlqr/batch/summary.hpp"
#include "sdlqr/tables/csv.hpp"
#include "batch_test_dir.hpp"
#include "../work_folder.hpp"

namespace sdlqr::batch {
namespace {

using ::sdlqr::test::fileText;
using test::kDir;

const std::string kRunWork = ::sdlqr::test::processWorkFolder("batch_run_test");
const auto* const kRemoveWorkFolder = ::sdlqr::test::removeAtExit(kRunWork);

std::string freshDir(const std::string& name) {
  const std::string dir = kRunWork + "/" + name;
  EXPECT_EQ(std::system(("rm -rf '" + dir + "'").c_str()), 0);
  return dir;
}

RunResult runIn(const BatchContext& context, const std::string& dir, int jobs, Shard shard = {}) {
  RunOptions options;
  options.out_dir = dir;
  options.jobs = jobs;
  options.shard = shard;
  options.progress = false;
  return runBatch(context, options);
}

class SmallBatch : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    context_ = new BatchContext(BatchContext::load(kDir + "/small_batch.yaml"));
    reference_ = new RunResult(runIn(*context_, freshDir("jobs1"), 1));
  }
  static void TearDownTestSuite() {
    delete context_;
    delete reference_;
  }
  static std::string referenceCsv() { return fileText(kRunWork + "/jobs1/flights.csv"); }
  static BatchContext* context_;
  static RunResult* reference_;
};
BatchContext* SmallBatch::context_ = nullptr;
RunResult* SmallBatch::reference_ = nullptr;

TEST_F(SmallBatch, OneRowPerFlightWithItsDrawsAndChecks) {
  const Table& t = reference_->table;
  ASSERT_EQ(t.rows.size(), 20u);
  EXPECT_EQ(reference_->flown, 20);
  std::set<std::string> names(t.header.begin(), t.header.end());
  EXPECT_EQ(names.size(), t.header.size()) << "a column named twice";
  for (size_t i = 0; i < t.rows.size(); ++i) {
    EXPECT_EQ(t.rows[i][0], std::to_string(i));
    EXPECT_EQ(std::stod(t.rows[i][t.column("vehicle.motor_time_constant")]), i % 2 ? 0.035 : 0.025);
  }
  for (const char* column : {"pass", "failed_checks", "jump_settle_time", "jump_settle_time.value", "pull_return_time",
                             "hover_error", "crashed", "crashed.value", "max_tilt_deg", "vehicle.mass", "scenario.disturbance_scale"}) {
    EXPECT_GE(t.column(column), 0) << column;
  }
  EXPECT_NEAR(reference_->simulated_s, 20 * 10.5, 1.0);
}

TEST_F(SmallBatch, SameRowsBitForBitWhateverTheJobs) {
  const std::string dir = freshDir("jobs3");
  runIn(*context_, dir, 3);
  EXPECT_EQ(fileText(dir + "/flights.csv"), referenceCsv());
}

TEST_F(SmallBatch, ShardsMergeIntoTheSingleRun) {
  std::vector<std::string> shards;
  for (int i = 1; i <= 4; ++i) {
    shards.push_back(freshDir("shard" + std::to_string(i)));
    const RunResult r = runIn(*context_, shards.back(), 2, Shard{i, 4});
    EXPECT_EQ(r.table.rows.size(), 5u);
  }
  const std::string merged = freshDir("merged");
  mergeShards(shards, merged, *context_);
  EXPECT_EQ(fileText(merged + "/flights.csv"), referenceCsv());
  EXPECT_EQ(fileText(merged + "/batch.yaml"), fileText(kRunWork + "/jobs1/batch.yaml"));
  EXPECT_EQ(summaryText(*context_, readTable(merged + "/flights.csv")), summaryText(*context_, reference_->table));

  // What merge refuses: a shard missing, a shard twice, an unfinished shard, another batch.
  EXPECT_THROW(mergeShards({shards[0], shards[1], shards[2]}, freshDir("m1"), *context_), std::runtime_error);
  EXPECT_THROW(mergeShards({shards[0], shards[1], shards[2], shards[2]}, freshDir("m2"), *context_), std::runtime_error);
  std::remove((shards[3] + "/flights.csv").c_str());
  EXPECT_THROW(mergeShards(shards, freshDir("m3"), *context_), std::runtime_error);
  const BatchContext other = BatchContext::load(kDir + "/nominal_plant.yaml");
  EXPECT_THROW(mergeShards({shards[0]}, freshDir("m4"), other), std::runtime_error);
}

TEST_F(SmallBatch, AKilledRunResumesWithoutFlyingAFinishedFlightAgain) {
  const std::string dir = freshDir("killed");
  const std::string journal = dir + "/flights.partial.csv";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const std::string exe = SDLQR_BINARY_DIR "/bin/sdlqr-batch", spec = kDir + "/small_batch.yaml";
    execl(exe.c_str(), exe.c_str(), spec.c_str(), "--out", dir.c_str(), "--jobs", "1", "--no-progress",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  // Kill it once at least three rows (and the header) have landed.
  auto rows = [&]() -> std::ptrdiff_t {
    if (!std::ifstream(journal).good()) return -1;  // not written yet
    const std::string text = fileText(journal);
    return std::count(text.begin(), text.end(), '\n') - 1;
  };
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (rows() < 3 && std::chrono::steady_clock::now() < give_up) std::this_thread::sleep_for(std::chrono::milliseconds(1));
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the batch ended before it was killed";
  const long long landed = rows();
  ASSERT_GE(landed, 3);
  ASSERT_LT(landed, 20);
  // Half a row, as a kill during a write leaves it.
  std::ofstream(journal, std::ios::app) << "99,sdlqr,12345,0.2";

  const RunResult resumed = runIn(*context_, dir, 2);
  EXPECT_EQ(resumed.resumed, landed);
  EXPECT_EQ(resumed.flown, 20 - landed);
  EXPECT_EQ(fileText(dir + "/flights.csv"), referenceCsv());
  const std::string journaled = fileText(journal);
  EXPECT_EQ(std::count(journaled.begin(), journaled.end(), '\n'), 21);  // header + 20, none twice
  // Again: nothing left to fly.
  const RunResult again = runIn(*context_, dir, 2);
  EXPECT_EQ(again.flown, 0);
  EXPECT_EQ(again.resumed, 20);
}

TEST_F(SmallBatch, AFolderOfAnotherBatchOrShardIsRefused) {
  const BatchContext other = BatchContext::load(kDir + "/nominal_plant.yaml");
  EXPECT_THROW(runIn(other, kRunWork + "/jobs1", 1), std::runtime_error);
  EXPECT_THROW(runIn(*context_, kRunWork + "/jobs1", 1, Shard{1, 2}), std::runtime_error);
}

TEST_F(SmallBatch, AReflownFlightReproducesItsRowFromItsFiles) {
  for (int flight : {4, 13}) {
    const std::string dir = freshDir("refly" + std::to_string(flight));
    makeDirectories(dir);
    const FlightDraw draw = drawFlight(context_->spec, context_->config, context_->scenario.sim, flight);
    writeFlightFiles(*context_, draw, "sdlqr", dir);
    const FlownFlight flown = fly(*context_, loadFlightFiles(dir), "sdlqr");
    std::ostringstream batch_row;
    tables::CsvWriter csv(batch_row);
    for (const std::string& cell : reference_->table.rows[static_cast<size_t>(flight)]) csv.name(cell);
    csv.endRow();
    EXPECT_EQ(row(*context_, draw, "sdlqr", flown.report), batch_row.str()) << flight;
  }
}

TEST_F(SmallBatch, ThePlantItselfChangesTheFlight) {
  // Flight 0 flown on the nominal plant differs from its perturbed row: the draws reach the plant.
  const FlightDraw draw = drawFlight(context_->spec, context_->config, context_->scenario.sim, 0);
  FlightWorld nominal{{context_->config.vehicle, context_->config.sim}, context_->scenario};
  nominal.scenario.seed = draw.seed;
  const FlownFlight flown = fly(*context_, nominal, "sdlqr");
  EXPECT_NE(row(*context_, draw, "sdlqr", flown.report), row(*context_, draw, "sdlqr", fly(*context_, worldOf(*context_, draw), "sdlqr").report));
}

long long passedFlights(const Table& t) {
  return std::count_if(t.rows.begin(), t.rows.end(), [&](const auto& r) { return r[t.column("pass")] == "1"; });
}

TEST(BatchRegions, APlantSixtyPercentHeavierFailsAndANominalOnePasses) {
  const BatchContext heavy = BatchContext::load(kDir + "/heavy_plant.yaml");
  const RunResult bad = runIn(heavy, freshDir("heavy"), 2);
  EXPECT_EQ(passedFlights(bad.table), 0);
  const BatchContext good = BatchContext::load(kDir + "/nominal_plant.yaml");
  const RunResult fine = runIn(good, freshDir("nominal"), 2);
  EXPECT_EQ(passedFlights(fine.table), static_cast<long long>(fine.table.rows.size()));
  const std::string summary = summaryText(heavy, bad.table);
  EXPECT_NE(summary.find("every check passed in 0/6"), std::string::npos) << summary;
  EXPECT_NE(summary.find("--refly"), std::string::npos);
  EXPECT_NE(summary.find("--plant-config"), std::string::npos);
}

// The cells of a row from its first parameter column on: what the flight drew and did.
std::vector<std::string> outcome(const Table& t, size_t row) {
  const auto& r = t.rows.at(row);
  return std::vector<std::string>(r.begin() + t.column("pass"), r.end());
}

TEST(BatchControllers, EachControllerFliesItsOwnLawOnTheSameDrawsOfTheStressedWorld) {
  const BatchContext context = BatchContext::load(kDir + "/controllers_in_wind.yaml");
  const RunResult result = runIn(context, freshDir("controllers"), 2);
  ASSERT_EQ(result.table.rows.size(), 6u);  // 2 flights x 3 controllers, flight-major
  const int wind = result.table.column("sim.wind.steady[0]");
  for (size_t flight = 0; flight < 2; ++flight) {
    const size_t sdlqr = 3 * flight, hover_lqr = sdlqr + 1, geometric = sdlqr + 2;
    EXPECT_EQ(result.table.rows[sdlqr][1], "sdlqr");
    EXPECT_EQ(result.table.rows[geometric][1], "geometric");
    EXPECT_EQ(result.table.rows[sdlqr][wind], result.table.rows[geometric][wind]);  // the same draw
    EXPECT_NE(outcome(result.table, sdlqr), outcome(result.table, hover_lqr));
    EXPECT_NE(outcome(result.table, sdlqr), outcome(result.table, geometric));
    EXPECT_NE(outcome(result.table, hover_lqr), outcome(result.table, geometric));
  }
  // The stressors reach the simulator: flight 0 without them flies another flight.
  const FlightDraw draw = drawFlight(context.spec, context.config, context.scenario.sim, 0);
  FlightWorld calm = worldOf(context, draw);
  calm.scenario.sim = sim::SimStress();
  EXPECT_NE(row(context, draw, "sdlqr", fly(context, calm, "sdlqr").report),
            row(context, draw, "sdlqr", fly(context, worldOf(context, draw), "sdlqr").report));
}

TEST(BatchControllers, AReflownFlightKeepsItsControllerAndItsStressors) {
  const BatchContext context = BatchContext::load(kDir + "/controllers_in_wind.yaml");
  const RunResult result = runIn(context, freshDir("controllers_refly_batch"), 2);
  const std::string dir = freshDir("controllers_refly");
  makeDirectories(dir);
  const FlightDraw draw = drawFlight(context.spec, context.config, context.scenario.sim, 1);
  writeFlightFiles(context, draw, "geometric", dir);
  EXPECT_EQ(loadYamlFile(dir + "/vehicle.yaml")["lqr"]["law"].as<std::string>(), "geometric");
  const FlightWorld files = loadFlightFiles(dir);
  EXPECT_EQ(files.scenario.sim.wind.steady.x(), draw.values[0]);
  EXPECT_EQ(files.scenario.sim.plant.thrust_scale, draw.values[2]);
  std::ostringstream batch_row;
  tables::CsvWriter csv(batch_row);
  for (const std::string& cell : result.table.rows[5]) csv.name(cell);  // flight 1, geometric
  csv.endRow();
  EXPECT_EQ(row(context, draw, "geometric", fly(context, files, "geometric").report), batch_row.str());
}

TEST(BatchRegions, RotorsAtHalfThrustFailTheSaturationCriterionAndTheNominalOnesPass) {
  const BatchContext weak = BatchContext::load(kDir + "/weak_rotors.yaml");
  const RunResult bad = runIn(weak, freshDir("weak_rotors"), 2);
  const int rotors = bad.table.column("rotor_at_limit_max");
  for (const auto& r : bad.table.rows) EXPECT_EQ(r[rotors], "0") << r[0];
  const BatchContext nominal = BatchContext::load(kDir + "/nominal_rotors.yaml");
  const RunResult fine = runIn(nominal, freshDir("nominal_rotors"), 2);
  for (const auto& r : fine.table.rows) EXPECT_EQ(r[rotors], "1") << r[0];
  EXPECT_EQ(passedFlights(fine.table), static_cast<long long>(fine.table.rows.size()));
}

}  // namespace
}  // namespace sdlqr::batch
