#pragma once
// What `sdlqr-compare --out DIR` writes (numbers as logger/csv.hpp prints them: they read back bit
// for bit; nothing depends on the machine, the clock or the thread count):
//
//   DIR/report.md                 the tables (compare_report.hpp)
//   DIR/flights.csv               one row per experiment and controller: pass, the checks, every
//                                 metric of compareMetrics()
//   DIR/sweep.csv                 one row per controller and speed asked: pass|fail|infeasible, the
//                                 flights (one per seed), the worst seed's path errors and tilt
//   DIR/tracks/<experiment>.csv   controller, t, x, y, z: SIM_TRUTH at 25 Hz, every controller
//   DIR/tracks/<experiment>.path.csv  segment, x, y, z: the uploaded trajectories' samples (when any)
//
// scripts/plot_compare.py draws DIR/plots/ from these.

#include <string>

#include "sdlqr/compare/compare_run.hpp"

namespace sdlqr::compare {

std::string flightsCsv(const CompareResult& result);
std::string sweepCsv(const CompareResult& result);
// Of the flights of one experiment.
std::string trackCsv(const CompareResult& result, const std::string& experiment);
std::string pathCsv(const CompareResult& result, const std::string& experiment);

// Every file above into `dir` (created); throws std::runtime_error naming a file it cannot write.
void writeCompareFiles(const Benchmark& benchmark, const CompareResult& result, const std::string& dir);

// The folder name of a benchmark among several: its file's name without ".yaml".
std::string benchmarkName(const Benchmark& benchmark);
// DIR/report.md for several benchmarks: the headline of them all (headline.hpp) and each one's report.
void writeHeadlineFile(const std::vector<Benchmark>& benchmarks, const std::vector<CompareResult>& results,
                       const std::string& dir);

// The names of a flight's failed checks, "; "-separated.
std::string failedChecks(const analysis::FlightReport& report);

}  // namespace sdlqr::compare
