#pragma once
// The speed sweep: one closed path (a circle, lemniscate or min-snap through waypoints, at a
// user-set speed) flown by one controller at each speed of the benchmark, slowest first, until a
// speed fails its `fail_on` criteria. A speed beyond the vehicle (the feasibility check every
// scenario's path gets: lqr c_min/c_max, omega_max) is no controller's failure: the sweep of every
// controller ends before it, and the report says so.

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "sdlqr/batch/flight.hpp"
#include "sdlqr/compare/benchmark.hpp"

namespace sdlqr::compare {

// The event whose speed the sweep sets: the scenario's one trajectory event with a speed
// (generator circle, lemniscate or waypoints). Throws ConfigError naming `where` otherwise.
size_t sweptEventIndex(const mission::Scenario& scenario, const std::string& where);

// The scenario with that event's speed set.
mission::Scenario atSpeed(const mission::Scenario& scenario, double speed);

struct SweepFlight {
  double speed = 0.0;                  // [m/s]
  bool feasible = true;
  bool pass = false;                   // every fail_on check passed, at least one was judged, no crash
  std::vector<std::string> failed;     // the flight's failed checks (fail_on or not)
  double path_error_rms = std::numeric_limits<double>::quiet_NaN();  // [m] worst trajectory
  double path_error_max = std::numeric_limits<double>::quiet_NaN();
  double max_tilt_deg = std::numeric_limits<double>::quiet_NaN();
  int flights = 0;                     // one per seed
  double simulated_s = 0.0;
};

struct SweepResult {
  std::string controller;
  std::vector<SweepFlight> flights;  // the speeds flown, slowest first
  double first_failing_speed = std::numeric_limits<double>::quiet_NaN();  // NaN: none failed
  double highest_passing_speed = std::numeric_limits<double>::quiet_NaN();
};

// Per speed of the sweep, empty when the path is feasible there, else the verdict
// ("events[3].trajectory: at 5 m/s the path is beyond the vehicle: ...").
std::vector<std::string> sweepRefusals(const batch::BatchContext& context, const std::vector<double>& speeds);

// One flight of a sweep passes when it judged at least one `fail_on` check, passed every one of them
// and did not crash: a crash after the path's errors were measured (in the exit, the hold, the
// landing) is no speed "flown within its criteria".
bool sweepFlightPasses(const analysis::FlightReport& report, const std::vector<std::string>& fail_on);

// One speed: a flight per seed, judged on `fail_on`; it passes when every seed's flight passes, its
// path errors and tilt are the worst seed's, its failed checks every seed's ("seed 1: crashed").
SweepFlight flySweepSpeed(const batch::BatchContext& context, const std::vector<std::string>& fail_on,
                          const std::string& controller, double speed, const std::vector<long long>& seeds);

// The seeds a sweep flies: the benchmark's seed when it sets one (or --seed), else the sweep's
// seeds, else the scenario's own.
std::vector<long long> sweepSeeds(const Benchmark& benchmark, const mission::Scenario& scenario);

// The sweep of one controller; `landed` hears of each speed flown (progress).
SweepResult flySweep(const batch::BatchContext& context, const SpeedSweep& sweep, const std::vector<long long>& seeds,
                     const std::vector<std::string>& refusals, const std::string& controller,
                     const std::function<void(const SweepFlight&)>& landed = {});

}  // namespace sdlqr::compare
