#pragma once
// A scenario file (config/scenarios/*.yaml): what to fly, when to push, and what counts as a pass.
//
//   name: hover_jumps
//   vehicle: ../quad255.yaml      # relative to this file
//   seed: 7                        # simulator noise seed
//   duration: 40.0                 # [s] simulation time; the run ends here
//   rate: 1.0                      # [-] simulation speed over wall time
//   events:                        # at [s] of simulation time, in any order
//     - {at: 1.0, command: arm}
//     - {at: 1.5, command: takeoff, height: 1.0}
//     - {at: 6.0, command: goto, position: [1, 0, 1], yaw: 0.0, label: "jump x"}
//     - {at: 20.0, disturbance: {force: [2, 0, 0], duration: 0.5}, label: pull}
//     - {at: 25.0, params: {r_diag: [1, 5, 5, 0.1]}}
//     - {at: 30.0, trajectory: {generator: minsnap_fast, laps: 3, tracking: spatial}}
//     - {at: 36.0, command: land}
//   criteria: {jump_settle_error: 0.05, jump_settle_time: 3.0}   # [m], [s], ... (see README)
//   sim: {plant: {mass_scale: 1.2}, wind: {...}, airborne_start: {...}, throw: {...}}  # sim/stress_params.hpp
//   throw_mode: {at: 1.0, type: throw}                           # the stack's throw start (throw_detector.hpp)

#include <map>
#include <string>
#include <vector>

#include "sdlqr/config/config.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/mission/throw_detector.hpp"
#include "sdlqr/sim/stress_params.hpp"

namespace sdlqr::mission {

// Unset optional fields (negative) take the vehicle file's `trajectory:` settings.
//
// Every trajectory (the paper's, aggressive closed paths at a user-set speed — circle, lemniscate,
// or min-snap through the waypoints of a YAML/CSV file —, a CSV file of samples) is checked when
// the scenario is loaded (trajectory/path_check.hpp: its inputs within the lqr limits, an entry from
// the hover before it and an exit from it that are flyable): beyond the vehicle it is refused with
// the report (on_infeasible: refuse), flown at the highest feasible speed (scale), or flown as it
// is with the report printed (fly: the paper's infeasible ellipse, §III-C.3, on purpose).
//   {generator: circle, speed: 3.0, size: 1.0, center: [0, 0, 1.5], v_max: 4.0, on_infeasible: scale}
//   {generator: waypoints, waypoints: path.yaml, speed: 2.0}
enum class OnInfeasible { kRefuse, kScale, kFly };

struct TrajectoryRequest {
  std::string generator;   // minsnap_fast, minsnap_slow, ellipse, csv, circle, lemniscate or waypoints
  std::string csv_path;    // for generator csv, resolved against the scenario folder
  std::string waypoints_path;  // for generator waypoints (YAML or CSV), resolved likewise
  double speed = -1.0;     // [m/s] peak speed of circle, lemniscate, waypoints (the file's v_max if unset)
  double size = 1.0;       // [m] circle radius, lemniscate half-width
  Vec3 center = Vec3(0.0, 0.0, 1.5);  // [m] of circle and lemniscate
  double v_max = -1.0;     // [m/s] speed limit of the check (unset: the requested speed, or the guard's)
  OnInfeasible on_infeasible = OnInfeasible::kRefuse;
  int laps = -1;           // [-] laps of the paper's paths
  ReferenceMode tracking = ReferenceMode::kSpatial;
  double height_offset = -1.0;  // [m] added to the paper's waypoint heights
  double sample_dt = -1.0;      // [s] sampling of generated trajectories (paper: 0.1 s)
};

struct ScenarioEvent {
  enum class Kind { kCommand, kDisturbance, kParams, kTrajectory };
  double at = 0.0;  // [s] simulation time
  Kind kind = Kind::kCommand;
  std::string label;
  Command command;
  Disturbance disturbance;
  ParamsUpdate params;
  TrajectoryRequest trajectory;
};

struct Scenario {
  std::string name;
  std::string description;
  std::string path;          // of the scenario file
  std::string vehicle_path;  // resolved
  long long seed = 1;
  double duration = 30.0;    // [s]
  double rate = 1.0;         // [-]
  std::vector<ScenarioEvent> events;  // sorted by time
  std::map<std::string, double> criteria;
  sim::SimStress sim;          // the simulated world only: the stack flies the vehicle file
  ThrowModeParams throw_mode;  // the stack: wait for a throw with the motors stopped

  // Throws ConfigError naming the key ("events[3].position") on any invalid entry.
  static Scenario load(const std::string& path);
  double criterion(const std::string& key, double fallback) const;
};

}  // namespace sdlqr::mission
