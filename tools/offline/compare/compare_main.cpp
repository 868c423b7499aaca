// sdlqr-compare: every controller law flies a benchmark of experiments and a speed sweep on the
// in-process closed loop; writes report.md and the CSVs the plots read (docs/controllers.md).
#include <algorithm>
#include <cstdio>
#include <thread>

#include "sdlqr/compare/bus_flights.hpp"
#include "sdlqr/compare/compare_files.hpp"
#include "sdlqr/compare/headline.hpp"
#include "sdlqr/config/cli.hpp"

namespace sdlqr::compare {
namespace {

int run(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string out_dir, controllers, scenarios, bus_files;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  long long seed = -1;
  bool quiet = false;
  ArgParser parser("sdlqr-compare",
                   "Every controller law flies one or more benchmarks on the in-process closed loop (one vehicle\n"
                   "each: the headline compares them per vehicle and law).");
  parser.allowPositional(&positional, "BENCHMARK.yaml...");
  parser.addOption("--out", &out_dir, "DIR",
                   "folder of report.md, flights.csv, sweep.csv, tracks/ (created); with several benchmarks\n"
                   "one folder each (DIR/<benchmark>/) and DIR/report.md the headline of them all");
  parser.addOption("--controllers", &controllers, "A,B", "only these controllers (default: the benchmark's)");
  parser.addOption("--scenarios", &scenarios, "A,B", "only these experiments (speed_sweep: the sweep)");
  parser.addOption("--seed", &seed, "N", "every flight's noise seed (default: the benchmark's, else each scenario's)",
                   Range::atLeast(0));
  parser.addOption("--jobs", &jobs, "N", "flights flown at once (default: every core); the files do not depend on it",
                   Range::atLeast(1));
  parser.addFlag("--quiet", &quiet, "no progress lines on stderr");
  parser.addOption("--bus-files", &bus_files, "DIR",
                   "instead: write DIR/<controller>/<experiment>/{vehicle,scenario}.yaml and DIR/plan.txt to\n"
                   "fly them over the bus (./sdlqr compare --bus), and exit");
  parser.setEpilog(
      "Benchmark keys: controllers, experiments, seed, speed_sweep {scenario, speeds, fail_on}\n"
      "(config/compare/benchmark.yaml). Exit codes: 0 written (whatever passed), 2 bad benchmark file or\n"
      "option, 1 other errors.");
  parser.parseOrExit(argc, argv);
  if (positional.empty()) throw ConfigError("BENCHMARK", "name a benchmark file (see --help)");
  if (out_dir.empty() && bus_files.empty()) throw ConfigError("--out", "name the output folder");
  const bool several = positional.size() > 1;
  if (several && !scenarios.empty()) throw ConfigError("--scenarios", "selects experiments of one benchmark file");
  if (several && !bus_files.empty()) throw ConfigError("--bus-files", "writes the flights of one benchmark file");
  std::vector<Benchmark> benchmarks;
  for (const std::string& path : positional) {
    Benchmark benchmark = Benchmark::load(path);
    if (!controllers.empty()) selectControllers(benchmark, controllers);
    if (!scenarios.empty()) selectScenarios(benchmark, scenarios);
    if (seed >= 0) benchmark.seed = seed;
    benchmarks.push_back(benchmark);
  }
  if (!bus_files.empty()) {
    const int flights = writeBusFlights(benchmarks[0], bus_files);
    std::fprintf(stderr, "compare: %d flights to fly over the bus -> %s/plan.txt\n", flights, bus_files.c_str());
    return 0;
  }

  CompareOptions options;
  options.jobs = jobs;
  options.progress = quiet ? nullptr : stderr;
  std::vector<CompareResult> results;
  for (const Benchmark& benchmark : benchmarks) {
    results.push_back(runCompare(benchmark, options));
    const std::string dir = several ? out_dir + "/" + benchmarkName(benchmark) : out_dir;
    writeCompareFiles(benchmark, results.back(), dir);
    std::fprintf(stderr, "compare: %d flights, %.0f s simulated in %.1f s on %d jobs -> %s/report.md\n",
                 results.back().flown, results.back().simulated_s, results.back().wall_s, jobs, dir.c_str());
  }
  if (several) {
    writeHeadlineFile(benchmarks, results, out_dir);
    std::fprintf(stderr, "compare: headline of %zu benchmarks -> %s/report.md\n", benchmarks.size(), out_dir.c_str());
  }
  return 0;
}

}  // namespace
}  // namespace sdlqr::compare

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-compare", [&] { return sdlqr::compare::run(argc, argv); });
}
