#include "sdlqr/compare/compare_losses.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/compare/compare_files.hpp"
#include "sdlqr/compare/compare_metrics.hpp"
#include "sdlqr/compare/compare_report.hpp"

namespace sdlqr::compare {

namespace {

std::string speedText(double v) { return std::isnan(v) ? "none" : formatValue(v, "m/s") + " m/s"; }

void experimentLosses(const ExperimentInfo& info, const CompareResult& result, std::vector<Loss>& out) {
  std::vector<const ExperimentFlight*> flights;
  const ExperimentFlight* paper = nullptr;
  for (const ExperimentFlight& f : result.flights) {
    if (f.experiment != info.name) continue;
    flights.push_back(&f);
    if (f.controller == kPaperController) paper = &f;
  }
  if (!paper) return;
  if (!paper->report.passed()) {
    std::string passing;
    for (const ExperimentFlight* f : flights) {
      if (f->report.passed()) passing += (passing.empty() ? "" : ", ") + f->controller;
    }
    if (!passing.empty()) out.push_back({info.name, "every check", "fails " + failedChecks(paper->report), passing, "pass"});
  }
  for (const batch::Metric& m : compareMetrics()) {
    const double mine = m.of(paper->report);
    if (std::isnan(mine)) continue;
    const ExperimentFlight* best = nullptr;
    double best_value = mine;
    for (const ExperimentFlight* f : flights) {
      const double v = m.of(f->report);
      if (f != paper && failsOnlyWhere(f->report, paper->report) && !std::isnan(v) && v < best_value) {
        best = f;
        best_value = v;
      }
    }
    if (!best || !(std::isinf(mine) || best_value < mine - kLossMargin * std::abs(mine))) continue;
    out.push_back({info.name, std::string(m.name) + " [" + m.unit + "]", formatValue(mine, m.unit), best->controller,
                   formatValue(best_value, m.unit)});
  }
}

}  // namespace

bool failsOnlyWhere(const analysis::FlightReport& other, const analysis::FlightReport& reference) {
  for (const analysis::Check& c : other.checks) {
    if (c.pass) continue;
    const bool reference_failed = std::any_of(reference.checks.begin(), reference.checks.end(),
                                              [&](const analysis::Check& r) { return r.name == c.name && !r.pass; });
    if (!reference_failed) return false;
  }
  return true;
}

std::vector<Loss> paperLosses(const CompareResult& result) {
  std::vector<Loss> out;
  for (const ExperimentInfo& info : result.experiments) experimentLosses(info, result, out);
  const auto paper = std::find_if(result.sweeps.begin(), result.sweeps.end(),
                                  [](const SweepResult& s) { return s.controller == kPaperController; });
  if (paper == result.sweeps.end() || std::isnan(paper->first_failing_speed)) return out;
  for (const SweepResult& other : result.sweeps) {
    const bool faster = std::isnan(other.first_failing_speed) || other.first_failing_speed > paper->first_failing_speed;
    if (&other != &*paper && faster) {
      out.push_back({kSweepName, "first failing speed", speedText(paper->first_failing_speed), other.controller,
                     speedText(other.first_failing_speed)});
    }
  }
  return out;
}

}  // namespace sdlqr::compare
