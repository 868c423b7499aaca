#include "sdlqr/compare/compare_files.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "sdlqr/batch/results.hpp"
#include "sdlqr/compare/compare_metrics.hpp"
#include "sdlqr/compare/compare_report.hpp"
#include "sdlqr/compare/headline.hpp"
#include "sdlqr/tables/csv.hpp"

namespace sdlqr::compare {

namespace {

std::vector<std::string> experimentNames(const CompareResult& result) {
  std::vector<std::string> names;
  for (const ExperimentFlight& f : result.flights) {
    if (names.empty() || names.back() != f.experiment) names.push_back(f.experiment);
  }
  return names;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : "; ") + item;
  return out;
}

}  // namespace

std::string failedChecks(const analysis::FlightReport& report) {
  std::vector<std::string> names;
  for (const analysis::Check& c : report.checks) {
    if (!c.pass) names.push_back(c.name);
  }
  return joined(names);
}

std::string flightsCsv(const CompareResult& result) {
  std::ostringstream text;
  tables::CsvWriter csv(text);
  for (const char* name : {"experiment", "controller", "seed", "pass", "checks_passed", "checks", "failed_checks"}) {
    csv.name(name);
  }
  for (const batch::Metric& m : compareMetrics()) csv.name(std::string(m.name) + " [" + m.unit + "]");
  csv.endRow();
  for (const ExperimentFlight& f : result.flights) {
    int passed = 0;
    for (const analysis::Check& c : f.report.checks) passed += c.pass ? 1 : 0;
    csv.name(f.experiment);
    csv.name(f.controller);
    csv.integer(f.seed);
    csv.integer(f.report.passed() ? 1 : 0);
    csv.integer(passed);
    csv.integer(static_cast<int64_t>(f.report.checks.size()));
    csv.name(failedChecks(f.report));
    for (const batch::Metric& m : compareMetrics()) csv.real(m.of(f.report));
    csv.endRow();
  }
  return text.str();
}

std::string sweepCsv(const CompareResult& result) {
  std::ostringstream text;
  tables::CsvWriter csv(text);
  for (const char* name : {"controller", "speed [m/s]", "result", "flights", "path_error_rms [m]",
                           "path_error_max [m]", "max_tilt_deg [deg]", "failed_checks"}) {
    csv.name(name);
  }
  csv.endRow();
  for (const SweepResult& s : result.sweeps) {
    for (const SweepFlight& f : s.flights) {
      csv.name(s.controller);
      csv.real(f.speed);
      csv.name(!f.feasible ? "infeasible" : (f.pass ? "pass" : "fail"));
      csv.integer(f.flights);
      csv.real(f.path_error_rms);
      csv.real(f.path_error_max);
      csv.real(f.max_tilt_deg);
      csv.name(joined(f.failed));
      csv.endRow();
    }
  }
  return text.str();
}

std::string trackCsv(const CompareResult& result, const std::string& experiment) {
  std::ostringstream text;
  tables::CsvWriter csv(text);
  for (const char* name : {"controller", "t [s]", "x [m]", "y [m]", "z [m]"}) csv.name(name);
  csv.endRow();
  for (const ExperimentFlight& f : result.flights) {
    if (f.experiment != experiment) continue;
    for (const TrackPoint& p : f.track) {
      csv.name(f.controller);
      csv.real(p.t);
      for (int i = 0; i < 3; ++i) csv.real(p.position[i]);
      csv.endRow();
    }
  }
  return text.str();
}

std::string pathCsv(const CompareResult& result, const std::string& experiment) {
  std::ostringstream text;
  tables::CsvWriter csv(text);
  for (const char* name : {"segment", "x [m]", "y [m]", "z [m]"}) csv.name(name);
  csv.endRow();
  // The uploads do not depend on the controller: the first flight's.
  for (const ExperimentFlight& f : result.flights) {
    if (f.experiment != experiment) continue;
    for (const PathPoint& p : f.path) {
      csv.integer(p.segment);
      for (int i = 0; i < 3; ++i) csv.real(p.position[i]);
      csv.endRow();
    }
    break;
  }
  return text.str();
}

std::string benchmarkName(const Benchmark& benchmark) {
  std::string name = benchmark.path.substr(benchmark.path.find_last_of('/') + 1);
  if (name.size() > 5 && name.compare(name.size() - 5, 5, ".yaml") == 0) name.resize(name.size() - 5);
  return name;
}

void writeHeadlineFile(const std::vector<Benchmark>& benchmarks, const std::vector<CompareResult>& results,
                       const std::string& dir) {
  std::vector<HeadlineRun> runs;
  std::string reports;
  for (size_t i = 0; i < benchmarks.size(); ++i) {
    runs.push_back({&benchmarks[i], &results[i]});
    reports += "- [" + benchmarkName(benchmarks[i]) + "](" + benchmarkName(benchmarks[i]) + "/report.md): " +
               std::to_string(results[i].flown) + " flights\n";
  }
  batch::writeText(dir + "/report.md",
                   "# Controller comparison: " + std::to_string(benchmarks.size()) + " benchmarks\n\n" +
                       headlineMarkdown(runs) + "## Reports\n\n" + reports);
}

void writeCompareFiles(const Benchmark& benchmark, const CompareResult& result, const std::string& dir) {
  batch::makeDirectories(dir + "/tracks");
  batch::makeDirectories(dir + "/summaries");
  for (const ExperimentFlight& f : result.flights) {
    std::ostringstream summary;
    analysis::writeSummary(f.report, summary);
    batch::writeText(dir + "/summaries/" + f.experiment + "-" + f.controller + ".txt", summary.str());
  }
  batch::writeText(dir + "/flights.csv", flightsCsv(result));
  if (!result.sweeps.empty()) {
    batch::writeText(dir + "/sweep.csv", sweepCsv(result));
  } else {
    std::remove((dir + "/sweep.csv").c_str());  // of an earlier run into the same folder
  }
  for (const std::string& name : experimentNames(result)) {
    batch::writeText(dir + "/tracks/" + name + ".csv", trackCsv(result, name));
    const std::string path = dir + "/tracks/" + name + ".path.csv";
    const bool uploads = std::any_of(result.flights.begin(), result.flights.end(),
                                     [&](const ExperimentFlight& f) { return f.experiment == name && !f.path.empty(); });
    if (uploads) {
      batch::writeText(path, pathCsv(result, name));
    } else {
      std::remove(path.c_str());
    }
  }
  batch::writeText(dir + "/report.md", reportMarkdown(benchmark, result));
}

}  // namespace sdlqr::compare
