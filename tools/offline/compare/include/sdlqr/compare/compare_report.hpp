#pragma once
// report.md of a comparison: a summary per controller, the speed sweep's headline table, one
// table per experiment (controllers x the metrics that apply to it, pass/fail and the failed
// checks) and where the paper's controller (sdlqr) is not the best. Numbers are rounded for
// reading (3 significant digits); flights.csv and sweep.csv hold them exactly. The text depends
// only on the benchmark and the flights: the same seed gives the same file.

#include <string>

#include "sdlqr/compare/compare_run.hpp"

namespace sdlqr::compare {

std::string reportMarkdown(const Benchmark& benchmark, const CompareResult& result);

// A metric value for a table: "—" when it does not apply (NaN), "never" when never reached (inf).
std::string formatValue(double value, const std::string& unit);

}  // namespace sdlqr::compare
