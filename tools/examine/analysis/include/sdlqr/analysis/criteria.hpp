#pragma once
// Every scenario criterion, declared once: its key in the scenario's `criteria:` map, whether the
// value must stay at or below the limit or at or above it, its unit, what it judges (a text that
// may name another key in braces, filled with that key's value from the scenario, so the label
// follows the threshold the scenario set) and where its value comes from. The checks of a report,
// the summary's table and the list of known keys all come from this table.
//
// Thresholds are the scenario keys that tune a measurement without being a check themselves
// (jump_settle_error sets the error a jump must settle below; jump_settle_time is the check).
//
// Relative budgets (keys ending in _relative_max) judge a machine-dependent figure against the
// same figure measured on the same machine just before the flight (Calibration): CPU and
// latency never decide a pass on their own, only a gross regression against this machine.

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::analysis {

enum class Bound { kAtMost, kAtLeast };

// What one value of a criterion belongs to: the flight, or each window of a kind. The windows are
// the scenario's (scenario_events.hpp): one check per event the criterion applies to, failing
// with the reason when the event is not in the log.
enum class Scope { kFlight, kEvent, kJump, kTakeoff, kSetpoint, kPull, kLanding, kTrajectory, kTrajectoryPull };

struct CriterionSpec {
  std::string_view key;
  Bound bound = Bound::kAtMost;
  std::string_view unit;         // of value and limit: "s", "m", "-", "Hz", "deg", "m/s", "count"
  std::string_view description;  // "{jump_settle_error}" is replaced by that key's value and unit
  Scope scope = Scope::kFlight;
  // The value judged; exactly the one matching `scope` is set.
  double (*of_flight)(const FlightReport&) = nullptr;
  double (*of_event)(const ExpectedEvent&) = nullptr;
  double (*of_landing)(const Landing&) = nullptr;
  double (*of_setpoint)(const SetpointWindow&) = nullptr;
  double (*of_pull)(const PullWindow&) = nullptr;
  double (*of_trajectory)(const PathTrackingReport&) = nullptr;
  double (*of_trajectory_pull)(const PathPull&) = nullptr;
  // Needs the calibration of this machine: not judged (listed as such) without one.
  bool needs_calibration = false;
  // Needs process HEARTBEATs (a bus flight): not judged in an in-process flight.
  bool needs_heartbeats = false;
  // Judged in every flight, against default_limit unless the scenario sets the key.
  bool always = false;
  double default_limit = 0.0;
};

struct ThresholdSpec {
  std::string_view key;
  std::string_view unit;
  std::string_view description;
};

const std::vector<CriterionSpec>& criteria();
const std::vector<ThresholdSpec>& thresholds();
const CriterionSpec* findCriterion(std::string_view key);
const ThresholdSpec* findThreshold(std::string_view key);

// "0.05 m" -> "5 cm" style text of a scenario value with its unit, for labels.
std::string formatQuantity(double value, std::string_view unit);
// The description with every "{key}" replaced by the scenario's value of that key (or its
// default when the scenario leaves it out), e.g. "settle time (error below 5 cm)".
std::string describe(const CriterionSpec& spec, const mission::Scenario& scenario, const AnalysisOptions& options);

// Throws std::invalid_argument naming "criteria.<key>" for a key neither table knows.
void checkCriteriaKeys(const mission::Scenario& scenario);

// Appends one Check per criterion the scenario names and per window it applies to, plus the
// checks every flight gets (no non-finite message, no crash, each scenario event in the log).
// Criteria that cannot be judged on this report (no calibration, no heartbeats) are listed in
// report.not_judged with the reason.
void judgeCriteria(FlightReport& report, const mission::Scenario& scenario, const AnalysisOptions& options);

}  // namespace sdlqr::analysis
