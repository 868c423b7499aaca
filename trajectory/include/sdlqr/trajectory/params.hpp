#pragma once
// Settings of trajectory generation and checking: the `trajectory:` section of a vehicle file.
// Defaults reproduce the paper's experiments (§III-C).

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/trajectory/validation.hpp"

namespace sdlqr::trajectory {

// Each member is declared once (key, unit, default, range, help) in trajectory/params/params.yaml
// (the rules across keys: params.cpp); the default constructor takes the defaults from there.
struct TrajectoryParams : DeclaredParams<TrajectoryParams> {
  double sample_dt;
  double check_dt;
  double height_offset;  // added to the paper's waypoint z (theirs start at 0)
  int laps;
  bool periodic;
  double yaw;
  double fast_v_max;
  double slow_v_max;
  double ellipse_speed;
  int ellipse_samples;
  double max_position_jump;
  double accel_mismatch_max;

  TrajectoryParams();
  static const ParamTable<TrajectoryParams>& declaration();

  SampleChecks sampleChecks() const;
};

}  // namespace sdlqr::trajectory
