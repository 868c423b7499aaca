#pragma once
// What every sampled trajectory must satisfy before a tracker or the CSV reader accepts it.
// Shared by both, so a trajectory that arrives over the bus and one read from a file are held to
// the same rules.
//
// Closed trajectories carry one full lap: the last sample closes it at the first sample's position
// (so the lap period is t_last - t_first and no wrap segment of unknown duration exists).

#include <string>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr::trajectory {

struct SampleChecks {
  double max_position_jump = 1.0;           // [m] between consecutive samples
  double quaternion_norm_tolerance = 1e-3;  // [-] allowed | ||q|| - 1 |
  double closure_tolerance = 1e-6;          // [m] last to first position of a closed trajectory
};

// Empty when fine, else the reason ("time not increasing"). `previous` may be null (first sample).
std::string checkSample(const TrajectorySample& sample, const TrajectorySample* previous, const SampleChecks& checks);

// Empty when fine, else "sample <k>: <reason>" for the first violation.
std::string validateTrajectory(const Trajectory& trajectory, const SampleChecks& checks);

// Empty when fine, else the closure violation of a closed trajectory (fewer than 2 samples included).
std::string checkClosure(const Trajectory& trajectory, const SampleChecks& checks);

}  // namespace sdlqr::trajectory
