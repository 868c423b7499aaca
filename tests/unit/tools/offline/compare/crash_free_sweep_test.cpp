// Issue 25, item 1: no law crashes on a path the check accepts. Every speed of a benchmark's sweep
// that the feasibility check accepts is flown by every law with every seed of the sweep, in
// process (the cores the executables run), and a crash at any of them fails the test — not only up
// to the first speed that misses the path criteria, as `./sdlqr compare` stops.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

#include "sdlqr/compare/benchmark.hpp"
#include "sdlqr/compare/experiment_flight.hpp"
#include "sdlqr/compare/sweep.hpp"

namespace sdlqr::compare {
namespace {

struct SweepCell {
  std::string law;
  double speed = 0.0;
  int crashes = 0;
  double worst_rms = 0.0;  // [m] worst seed
  double worst_max = 0.0;
  double worst_tilt_deg = 0.0;
};

// Every accepted speed x every law x every seed of the benchmark's sweep.
std::vector<SweepCell> flyEveryAcceptedSpeed(const std::string& benchmark_path, int& refused) {
  const Benchmark benchmark = Benchmark::load(benchmark_path);
  const batch::BatchContext context = scenarioContext(benchmark.sweep.scenario_path, benchmark.controllers, -1);
  const std::vector<std::string> refusals = sweepRefusals(context, benchmark.sweep.speeds);
  const std::vector<long long> seeds = sweepSeeds(benchmark, context.scenario);
  std::vector<SweepCell> cells;
  refused = 0;
  for (size_t i = 0; i < benchmark.sweep.speeds.size(); ++i) {
    if (!refusals[i].empty()) {
      ++refused;
      continue;
    }
    for (const std::string& law : benchmark.controllers) {
      SweepCell cell{law, benchmark.sweep.speeds[i]};
      for (long long seed : seeds) {
        batch::FlightWorld world{{context.config.vehicle, context.config.sim}, atSpeed(context.scenario, cell.speed)};
        world.scenario.seed = seed;
        const analysis::FlightReport r = batch::fly(context, world, law).report;
        cell.crashes += r.crashed ? 1 : 0;
        for (const analysis::PathTrackingReport& t : r.trajectories) {
          cell.worst_rms = std::max(cell.worst_rms, t.path_error_rms);
          cell.worst_max = std::max(cell.worst_max, t.path_error_max);
        }
        cell.worst_tilt_deg = std::max(cell.worst_tilt_deg, r.max_tilt_deg);
      }
      cells.push_back(cell);
    }
  }
  return cells;
}

void expectNoCrash(const std::string& benchmark_path) {
  int refused = 0;
  const std::vector<SweepCell> cells = flyEveryAcceptedSpeed(benchmark_path, refused);
  ASSERT_FALSE(cells.empty()) << "zero speeds accepted is no test";
  std::printf("%s: %zu law x speed cells flown, %d speeds refused by the check\n", benchmark_path.c_str(),
              cells.size(), refused);
  for (const SweepCell& c : cells) {
    std::printf("  %-15s %5.2f m/s: path error RMS %.3f m, max %.3f m, tilt %.1f deg%s\n", c.law.c_str(), c.speed,
                c.worst_rms, c.worst_max, c.worst_tilt_deg, c.crashes ? "  CRASHED" : "");
    EXPECT_EQ(c.crashes, 0) << c.law << " crashed at " << c.speed << " m/s, a speed the check accepts";
  }
}

TEST(CrashFreeSweep, EveryLawFliesEveryAcceptedSpeedOfThePapersVehicleWithEverySeed) {
  expectNoCrash(SDLQR_SOURCE_DIR "/config/compare/benchmark.yaml");
}

TEST(CrashFreeSweep, EveryLawFliesEveryAcceptedSpeedOfTheAgileCircleWithEverySeed) {
  expectNoCrash(SDLQR_SOURCE_DIR "/config/compare/agile752.yaml");
}

TEST(CrashFreeSweep, EveryLawFliesEveryAcceptedSpeedOfTheAgileLemniscateWithEverySeed) {
  expectNoCrash(SDLQR_SOURCE_DIR "/config/compare/agile752_lemniscate.yaml");
}

}  // namespace
}  // namespace sdlqr::compare
