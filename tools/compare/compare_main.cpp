// sdlqr-compare: every controller law flies a benchmark of experiments and a speed sweep on the
// in-process closed loop; writes report.md and the CSVs the plots read (docs/controllers.md).
#include <algorithm>
#include <cstdio>
#include <thread>

#include "sdlqr/compare/bus_flights.hpp"
#include "sdlqr/compare/compare_files.hpp"
#include "sdlqr/config/cli.hpp"

namespace sdlqr::compare {
namespace {

int run(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string out_dir, controllers, scenarios, bus_files;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  long long seed = -1;
  bool quiet = false;
  ArgParser parser("sdlqr-compare", "Every controller law flies a benchmark on the in-process closed loop.");
  parser.allowPositional(&positional, "BENCHMARK.yaml");
  parser.addOption("--out", &out_dir, "DIR", "folder of report.md, flights.csv, sweep.csv, tracks/ (created)");
  parser.addOption("--controllers", &controllers, "A,B", "only these controllers (default: the benchmark's)");
  parser.addOption("--scenarios", &scenarios, "A,B", "only these experiments (speed_sweep: the sweep)");
  parser.addOption("--seed", &seed, "N", "every flight's noise seed (default: the benchmark's, else each scenario's)");
  parser.addOption("--jobs", &jobs, "N", "flights flown at once (default: every core); the files do not depend on it");
  parser.addFlag("--quiet", &quiet, "no progress lines on stderr");
  parser.addOption("--bus-files", &bus_files, "DIR",
                   "instead: write DIR/<controller>/<experiment>/{vehicle,scenario}.yaml and DIR/plan.txt to\n"
                   "fly them over the bus (./sdlqr compare --bus), and exit");
  parser.setEpilog(
      "Benchmark keys: controllers, experiments, seed, speed_sweep {scenario, speeds, fail_on}\n"
      "(config/compare/benchmark.yaml). Exit codes: 0 written (whatever passed), 2 bad benchmark file or\n"
      "option, 1 other errors.");
  parser.parseOrExit(argc, argv);
  if (positional.size() != 1) throw ConfigError("BENCHMARK", "name one benchmark file (see --help)");
  if (out_dir.empty() && bus_files.empty()) throw ConfigError("--out", "name the output folder");
  if (jobs < 1) throw ConfigError("--jobs", "must be >= 1");
  if (seed < -1) throw ConfigError("--seed", "must be >= 0");
  Benchmark benchmark = Benchmark::load(positional[0]);
  if (!controllers.empty()) selectControllers(benchmark, controllers);
  if (!scenarios.empty()) selectScenarios(benchmark, scenarios);
  if (seed >= 0) benchmark.seed = seed;
  if (!bus_files.empty()) {
    const int flights = writeBusFlights(benchmark, bus_files);
    std::fprintf(stderr, "compare: %d flights to fly over the bus -> %s/plan.txt\n", flights, bus_files.c_str());
    return 0;
  }

  CompareOptions options;
  options.jobs = jobs;
  options.progress = quiet ? nullptr : stderr;
  const CompareResult result = runCompare(benchmark, options);
  writeCompareFiles(benchmark, result, out_dir);
  std::fprintf(stderr, "compare: %d flights, %.0f s simulated in %.1f s on %d jobs -> %s/report.md\n", result.flown,
               result.simulated_s, result.wall_s, jobs, out_dir.c_str());
  return 0;
}

}  // namespace
}  // namespace sdlqr::compare

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-compare", [&] { return sdlqr::compare::run(argc, argv); });
}
