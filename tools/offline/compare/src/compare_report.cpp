#include "sdlqr/compare/compare_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "sdlqr/compare/compare_files.hpp"
#include "sdlqr/compare/compare_losses.hpp"
#include "sdlqr/compare/compare_metrics.hpp"
#include "sdlqr/compare/headline.hpp"

namespace sdlqr::compare {

namespace {

using Flights = std::vector<const ExperimentFlight*>;

std::string printf3g(double value) {
  char text[40];
  std::snprintf(text, sizeof text, std::abs(value) >= 1000.0 ? "%.0f" : "%.3g", value);
  return text;
}

std::string sourceRelative(const std::string& path) {
  const std::string root = std::string(SDLQR_SOURCE_DIR) + "/";
  return path.compare(0, root.size(), root) == 0 ? path.substr(root.size()) : path;
}

std::string code(const std::string& text) { return "`" + text + "`"; }

Flights flightsOf(const CompareResult& result, const std::string& experiment) {
  Flights out;
  for (const ExperimentFlight& f : result.flights) {
    if (f.experiment == experiment) out.push_back(&f);
  }
  return out;
}

std::string checksCell(const analysis::FlightReport& r) {
  int passed = 0;
  for (const analysis::Check& c : r.checks) passed += c.pass ? 1 : 0;
  return (r.passed() ? "pass " : "**FAIL** ") + std::to_string(passed) + "/" + std::to_string(r.checks.size());
}

std::string speed(double v) { return std::isnan(v) ? "—" : printf3g(v) + " m/s"; }

// Markdown table cells must not hold a '|'.
std::string cell(std::string text) {
  for (size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.replace(at, 1, "\\|");
  return text;
}

void summary(std::ostream& out, const Benchmark& benchmark, const CompareResult& result) {
  out << "## Summary\n\n| controller | experiments passing every check |";
  if (!result.sweeps.empty()) out << " " << kSweepName << ": first failing speed |";
  out << "\n| --- | --- |" << (result.sweeps.empty() ? "" : " --- |") << "\n";
  for (size_t c = 0; c < benchmark.controllers.size(); ++c) {
    const std::string& controller = benchmark.controllers[c];
    int passed = 0;
    std::string failed;
    for (const ExperimentFlight& f : result.flights) {
      if (f.controller != controller) continue;
      if (f.report.passed()) {
        ++passed;
      } else {
        failed += (failed.empty() ? "" : ", ") + f.experiment;
      }
    }
    out << "| " << code(controller) << " | " << passed << " / " << result.experiments.size()
        << (failed.empty() ? "" : " (fails " + failed + ")") << " |";
    if (!result.sweeps.empty()) {
      const SweepResult& s = result.sweeps[c];
      out << " " << (std::isnan(s.first_failing_speed) ? "none up to " + speed(s.highest_passing_speed)
                                                        : "**" + speed(s.first_failing_speed) + "**")
          << " |";
    }
    out << "\n";
  }
  out << "\n";
}

void sweepSection(std::ostream& out, const Benchmark& benchmark, const CompareResult& result) {
  const SpeedSweep& sweep = benchmark.sweep;
  out << "## " << kSweepName << ": " << result.sweep.name << "\n\n"
      << result.sweep.description << " (" << code(sourceRelative(result.sweep.scenario_path)) << ", "
      << (result.sweep_seeds.size() > 1 ? "seeds " : "seed ");
  for (size_t i = 0; i < result.sweep_seeds.size(); ++i) out << (i ? ", " : "") << result.sweep_seeds[i];
  out << (result.sweep_seeds.size() > 1 ? ": a speed passes when it passes with every seed, its errors are the worst seed's"
                                        : "")
      << "). Each controller flies it at rising speed, slowest first, until a speed fails ";
  for (size_t i = 0; i < sweep.fail_on.size(); ++i) {
    out << (i ? " or " : "") << code(sweep.fail_on[i]) << " ≤ " << printf3g(result.sweep_limits[i]) << " m";
  }
  out << ".";
  for (size_t i = 0; i < result.refusals.size(); ++i) {
    if (result.refusals[i].empty()) continue;
    out << " From " << speed(sweep.speeds[i]) << " the path is beyond the vehicle and flown by no controller ("
        << result.refusals[i] << ").";
    break;
  }
  out << "\n\n| controller | first failing speed | highest passing speed | failed at the first failing speed |\n"
         "| --- | --- | --- | --- |\n";
  for (const SweepResult& s : result.sweeps) {
    const std::string failed = !s.flights.empty() && s.flights.back().feasible && !s.flights.back().pass
                                   ? [&] {
                                       std::string text;
                                       for (const std::string& f : s.flights.back().failed) text += (text.empty() ? "" : "; ") + f;
                                       return text;
                                     }()
                                   : std::string("—");
    out << "| " << code(s.controller) << " | "
        << (std::isnan(s.first_failing_speed) ? "none" : "**" + speed(s.first_failing_speed) + "**") << " | "
        << speed(s.highest_passing_speed) << " | " << cell(failed) << " |\n";
  }
  out << "\nPath error RMS / max [m] at each speed (empty: not flown, the controller failed a lower speed):\n\n| speed |";
  for (const SweepResult& s : result.sweeps) out << " " << code(s.controller) << " |";
  out << "\n| --- |";
  for (size_t c = 0; c < result.sweeps.size(); ++c) out << " --- |";
  out << "\n";
  for (size_t i = 0; i < sweep.speeds.size(); ++i) {
    out << "| " << speed(sweep.speeds[i]) << (result.refusals[i].empty() ? "" : " (beyond the vehicle)") << " |";
    for (const SweepResult& s : result.sweeps) {
      if (i >= s.flights.size()) {
        out << " |";
        continue;
      }
      const SweepFlight& f = s.flights[i];
      if (!f.feasible) {
        out << " beyond the vehicle |";
        continue;
      }
      const std::string text = formatValue(f.path_error_rms, "m") + " / " + formatValue(f.path_error_max, "m");
      out << " " << (f.pass ? text : "**" + text + " fail**") << " |";
    }
    out << "\n";
  }
  out << "\n![" << kSweepName << "](plots/" << kSweepName << ".png)\n\n";
}

void experimentSection(std::ostream& out, const ExperimentInfo& info, const Flights& flights) {
  std::vector<const batch::Metric*> shown;
  for (const batch::Metric& m : compareMetrics()) {
    for (const ExperimentFlight* f : flights) {
      if (!std::isnan(m.of(f->report))) {
        shown.push_back(&m);
        break;
      }
    }
  }
  out << "## " << info.name << "\n\n" << info.description << " (" << code(sourceRelative(info.scenario_path))
      << ", seed " << info.seed << ")\n\n| controller | checks |";
  for (const batch::Metric* m : shown) out << " " << m->name << " [" << m->unit << "] |";
  out << " failed checks |\n| --- | --- |";
  for (size_t i = 0; i < shown.size(); ++i) out << " --- |";
  out << " --- |\n";
  for (const ExperimentFlight* f : flights) {
    out << "| " << code(f->controller) << " | " << checksCell(f->report) << " |";
    for (const batch::Metric* m : shown) out << " " << formatValue(m->of(f->report), m->unit) << " |";
    const std::string failed = failedChecks(f->report);
    out << " " << cell(failed.empty() ? "—" : failed) << " |\n";
  }
  out << "\n![" << info.name << "](plots/" << info.name << ".png)\n\n";
}

// Where sdlqr is not the best (compare_losses.hpp), when it is compared with another controller.
void lossesSection(std::ostream& out, const Benchmark& benchmark, const CompareResult& result) {
  const bool compared = std::find(benchmark.controllers.begin(), benchmark.controllers.end(), kPaperController) !=
                            benchmark.controllers.end() &&
                        benchmark.controllers.size() > 1;
  if (!compared) return;
  out << "## Where " << kPaperController << " is not the best\n\n"
      << "Every experiment and metric where another controller is more than " << printf3g(100.0 * kLossMargin)
      << " % lower (better) than " << code(kPaperController) << ", with the best of them (among the controllers that "
      << "failed no check " << code(kPaperController) << " passed); every experiment it fails that another passes; "
      << "every controller whose sweep goes faster.\n\n";
  const std::vector<Loss> losses = paperLosses(result);
  if (losses.empty()) {
    out << "None.\n\n";
    return;
  }
  out << "| experiment | metric | " << code(kPaperController) << " | better |\n| --- | --- | --- | --- |\n";
  for (const Loss& l : losses) {
    out << "| " << l.experiment << " | " << l.what << " | " << cell(l.paper) << " | " << code(l.better) << " "
        << l.value << " |\n";
  }
  out << "\n";
}

}  // namespace

std::string formatValue(double value, const std::string& unit) {
  if (std::isnan(value)) return "—";
  if (std::isinf(value)) return value > 0 ? "never" : "-inf";
  if (unit == "count") return printf3g(std::round(value));
  return printf3g(value);
}

std::string reportMarkdown(const Benchmark& benchmark, const CompareResult& result) {
  std::ostringstream out;
  out << "# Controller comparison\n\n"
      << "Benchmark " << code(sourceRelative(benchmark.path)) << ": " << result.flown << " flights, "
      << printf3g(result.simulated_s) << " s simulated on the in-process closed loop (the process cores the "
      << "executables run, nominal plant, each scenario's stressors and criteria); seeds: "
      << (benchmark.seed >= 0 ? std::to_string(benchmark.seed) + " for every flight" : std::string("each scenario's own"))
      << ". Controllers (`lqr.law`):";
  for (const std::string& c : benchmark.controllers) out << " " << code(c);
  out << ".\n\nLower is better in every metric column; `never`: applies but was never reached, `—`: does not "
         "apply. Exact values: `flights.csv`, `sweep.csv`; tracks: `tracks/`; plots: `plots/` "
         "(`scripts/plot_compare.py`, none with `--no-plots`).\n\n";
  out << headlineMarkdown({{&benchmark, &result}});
  summary(out, benchmark, result);
  if (!result.sweeps.empty()) sweepSection(out, benchmark, result);
  for (const ExperimentInfo& info : result.experiments) experimentSection(out, info, flightsOf(result, info.name));
  lossesSection(out, benchmark, result);
  return out.str();
}

}  // namespace sdlqr::compare
