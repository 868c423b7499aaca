#pragma once
// Settings of trajectory generation and checking: the `trajectory:` section of a vehicle file.
// Defaults reproduce the paper's experiments (§III-C).

#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/trajectory/validation.hpp"

namespace sdlqr::trajectory {

struct TrajectoryParams {
  double sample_dt = 0.1;           // [s] sample spacing of generated trajectories (paper: 0.1 s)
  double check_dt = 0.001;          // [s] grid of the speed and input feasibility checks
  double height_offset = 1.0;       // [m] added to the paper's waypoint z (theirs start at 0)
  int laps = 2;                     // [-] laps of the paper's rest-to-rest min-snap path
  bool periodic = false;            // [-] paper min-snap as one periodic lap, repeated by the tracker
  double yaw = 0.0;                 // [rad] heading where waypoints give none
  double fast_v_max = 3.0;          // [m/s] §III-C.2
  double slow_v_max = 1.0;          // [m/s] §III-C.4
  double ellipse_speed = 2.0;       // [m/s] §III-C.3
  int ellipse_samples = 36;         // [-] samples per lap of the ellipse, d alpha = 2 pi / n
  double max_position_jump = 1.0;   // [m] largest step between samples accepted from a file or the bus
  double accel_mismatch_max = 0.5;  // [m/s^2] sampled trajectories: inputs vs motion (feasibility.hpp)

  // Reads the `trajectory` mapping; throws ConfigError naming the key.
  static TrajectoryParams load(const ConfigReader& trajectory);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }

  SampleChecks sampleChecks() const;
};

}  // namespace sdlqr::trajectory
