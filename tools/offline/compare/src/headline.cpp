#include "sdlqr/compare/headline.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "sdlqr/compare/compare_losses.hpp"

namespace sdlqr::compare {

namespace {

constexpr const char* kRivals[] = {"hover_lqr", "geometric"};

std::string format3g(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

// What a sweep says of one law: its fastest speed within the criteria and the path error there.
struct SweepOutcome {
  double fastest = std::nan("");  // [m/s] NaN: none passed
  double rms = std::nan(""), max = std::nan("");
  bool at_check_limit = false;    // the next speed of the sweep is beyond the vehicle
  bool stopped = false;           // a speed the check accepted failed
};

SweepOutcome outcomeOf(const SweepResult& s) {
  SweepOutcome o;
  o.fastest = s.highest_passing_speed;
  o.stopped = !std::isnan(s.first_failing_speed);
  for (size_t i = 0; i < s.flights.size(); ++i) {
    const SweepFlight& f = s.flights[i];
    if (f.feasible && f.speed == o.fastest) {
      o.rms = f.path_error_rms;
      o.max = f.path_error_max;
    }
    if (!f.feasible && i > 0 && s.flights[i - 1].speed == o.fastest) o.at_check_limit = true;
  }
  return o;
}

std::string sweepCell(const SweepOutcome& o) {
  if (std::isnan(o.fastest)) return "none passed";
  std::string text = "**" + format3g(o.fastest) + " m/s** (" + format3g(o.rms) + " / " + format3g(o.max) + " m)";
  if (o.at_check_limit) text += ", the check's limit";
  return text;
}

struct Row {
  std::string vehicle, law;
  int passed = 0, experiments = 0;
  std::map<std::string, std::string> sweeps;        // sweep name -> cell
  std::map<std::string, SweepOutcome> outcomes;     // sweep name -> outcome
  std::map<std::string, bool> experiment_passed;    // experiment -> passed
};

std::string vehicleName(const CompareResult& result) {
  std::string path = result.vehicle_path;
  const auto slash = path.find_last_of('/');
  if (slash != std::string::npos) path = path.substr(slash + 1);
  if (path.size() > 5 && path.compare(path.size() - 5, 5, ".yaml") == 0) path.resize(path.size() - 5);
  return path;
}

Row& rowFor(std::vector<Row>& rows, const std::string& vehicle, const std::string& law) {
  for (Row& r : rows) {
    if (r.vehicle == vehicle && r.law == law) return r;
  }
  Row row;
  row.vehicle = vehicle;
  row.law = law;
  rows.push_back(row);
  return rows.back();
}

// The paper's law against one rival on one vehicle: sweeps faster or slower, experiments passed
// that the other fails and the reverse.
std::string versus(const Row& paper, const Row& rival, const std::vector<std::string>& sweeps) {
  std::string text = "- " + std::string(kPaperController) + " vs `" + rival.law + "`:";
  for (const std::string& name : sweeps) {
    const auto a = paper.outcomes.find(name), b = rival.outcomes.find(name);
    if (a == paper.outcomes.end() || b == rival.outcomes.end()) continue;
    const double x = std::isnan(a->second.fastest) ? 0.0 : a->second.fastest;
    const double y = std::isnan(b->second.fastest) ? 0.0 : b->second.fastest;
    text += " " + name + ": " + (x > y ? "**wins**" : x < y ? "**loses**" : "ties") + " (" + format3g(x) + " vs " +
            format3g(y) + " m/s";
    if (x == y && x > 0.0) text += ", RMS " + format3g(a->second.rms) + " vs " + format3g(b->second.rms) + " m";
    text += ");";
  }
  std::string wins, losses;
  for (const auto& [experiment, passed] : paper.experiment_passed) {
    const auto other = rival.experiment_passed.find(experiment);
    if (other == rival.experiment_passed.end() || passed == other->second) continue;
    (passed ? wins : losses) += (passed ? wins : losses).empty() ? experiment : ", " + experiment;
  }
  text += " passes where it fails: " + (wins.empty() ? std::string("none") : wins) +
          "; fails where it passes: " + (losses.empty() ? std::string("none") : losses) + ".\n";
  return text;
}

}  // namespace

std::string headlineMarkdown(const std::vector<HeadlineRun>& runs) {
  std::vector<Row> rows;
  std::vector<std::string> vehicles;
  std::map<std::string, std::vector<std::string>> sweeps_of;  // vehicle -> sweep names
  for (const HeadlineRun& run : runs) {
    const std::string vehicle = vehicleName(*run.result);
    if (std::find(vehicles.begin(), vehicles.end(), vehicle) == vehicles.end()) vehicles.push_back(vehicle);
    for (const std::string& law : run.benchmark->controllers) {
      Row& row = rowFor(rows, vehicle, law);
      for (const ExperimentFlight& f : run.result->flights) {
        if (f.controller != law) continue;
        ++row.experiments;
        row.passed += f.report.passed() ? 1 : 0;
        row.experiment_passed[f.experiment] = f.report.passed();
      }
    }
    for (const SweepResult& s : run.result->sweeps) {
      Row& row = rowFor(rows, vehicle, s.controller);
      const std::string& name = run.result->sweep.name;
      row.outcomes[name] = outcomeOf(s);
      row.sweeps[name] = sweepCell(row.outcomes[name]);
      auto& names = sweeps_of[vehicle];
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  std::ostringstream out;
  out << "## Headline\n\nPer vehicle and law: the fastest speed of each sweep flown within its criteria (every "
         "seed), with the worst seed's path error RMS / max there; \"the check's limit\" where the next speed is "
         "beyond the vehicle (feasibility check); the experiments passing every check.\n\n";
  for (const std::string& vehicle : vehicles) {
    const std::vector<std::string>& names = sweeps_of[vehicle];
    out << "| vehicle | law | experiments passed |";
    for (const std::string& n : names) out << " " << n << " |";
    out << "\n| --- | --- | --- |";
    for (size_t i = 0; i < names.size(); ++i) out << " --- |";
    out << "\n";
    const Row* paper = nullptr;
    for (const Row& r : rows) {
      if (r.vehicle != vehicle) continue;
      if (r.law == kPaperController) paper = &r;
      out << "| " << vehicle << " | `" << r.law << "` | " << r.passed << " / " << r.experiments << " |";
      for (const std::string& n : names) {
        const auto it = r.sweeps.find(n);
        out << " " << (it == r.sweeps.end() ? std::string("—") : it->second) << " |";
      }
      out << "\n";
    }
    out << "\n";
    if (!paper) continue;
    for (const char* rival : kRivals) {
      for (const Row& r : rows) {
        if (r.vehicle == vehicle && r.law == rival) out << versus(*paper, r, names);
      }
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace sdlqr::compare
