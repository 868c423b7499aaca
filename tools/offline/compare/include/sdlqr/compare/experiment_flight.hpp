#pragma once
// One experiment of the benchmark flown by one controller on the in-process closed loop (the
// batch's fly(): the nominal plant, the scenario's criteria and stressors), and what the report
// and the plots keep of it: the analysis and the vehicle's track.

#include <string>
#include <vector>

#include "sdlqr/batch/flight.hpp"

namespace sdlqr::compare {

struct TrackPoint {
  double t = 0.0;  // [s] simulation time
  Vec3 position = Vec3::Zero();  // [m] SIM_TRUTH
};

// A sample of an uploaded trajectory: the path the plots draw under the tracks.
struct PathPoint {
  int segment = 0;  // which upload of the flight
  Vec3 position = Vec3::Zero();
};

// SIM_TRUTH (250 Hz) kept at 25 Hz: enough to draw, small enough to keep every flight.
inline constexpr int kTrackDecimation = 10;

struct ExperimentFlight {
  std::string experiment;
  std::string controller;
  long long seed = 0;
  double simulated_s = 0.0;
  analysis::FlightReport report;
  std::vector<TrackPoint> track;
  std::vector<PathPoint> path;
};

// `context.scenario` is flown as it is (its seed set by the caller); MOTOR_CMD is recorded so the
// rotor saturation is counted for every experiment.
ExperimentFlight flyExperiment(const batch::BatchContext& context, const std::string& controller);

// The context of one scenario file, every flight with `seed` (>= 0) or the scenario's own (-1).
batch::BatchContext scenarioContext(const std::string& scenario_path, const std::vector<std::string>& controllers,
                                    long long seed);

}  // namespace sdlqr::compare
