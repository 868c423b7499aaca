#pragma once
// How a vehicle recovered from a bad start: an airborne start in any attitude (the scenario's
// sim.airborne_start, recovery from t = 0) or a throw (sim.throw, recovery from the ARM the
// throw detector sent). Judged on SIM_TRUTH against the controller's REFERENCE of each moment,
// over the window from the start of the recovery to the first LAND (or the end of the log).

#include <optional>

#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::analysis {

struct RecoveryOptions {
  double level_tilt_deg = 10.0;  // [deg] level: tilt at most this, and staying
  double settle_error = 0.10;    // [m] settled: within this of the final hold, and staying
};

struct RecoveryReport {
  bool throw_start = false;
  double start = 0.0;            // [s] the recovery begins (0, or the throw's ARM)
  double release = 0.0;          // [s] throw: the hand let go
  double detect_delay;           // [s] throw: ARM after the release (NaN: never detected)
  double level_time;             // [s] after start, tilt below level_tilt_deg for good
  double height_lost;            // [m] z at the start minus the lowest z after it
  double settle_time;            // [s] after start, within settle_error of the final hold for good
                                 // (the reference before the landing: a recovering controller's
                                 // reference follows the vehicle until it holds)
  double initial_tilt_deg = 0.0; // [deg] at the start
};

// Empty when the scenario has neither an airborne start nor a throw.
std::optional<RecoveryReport> analyzeRecovery(const logger::FlightLog& log, const mission::Scenario& scenario,
                                              const RecoveryOptions& options);

}  // namespace sdlqr::analysis
