#pragma once
// Drives an Estimator with a SensorSimulator's events and scores every output against the
// analytic truth at the output's own time.

#include <cstdint>
#include <functional>
#include <vector>

#include "sdlqr/estimator/estimator.hpp"
#include "sensor_simulator.hpp"

namespace sdlqr::estimator::test {

// A bus utime [us] in seconds.
inline double seconds(int64_t utime) { return 1e-6 * static_cast<double>(utime); }

struct OutputRecord {
  StateEstimate estimate;
  double position_error = 0.0;  // [m] norm
  double attitude_error = 0.0;  // [rad] angle of the rotation from truth to estimate
  double velocity_error = 0.0;  // [m/s] norm
};

struct RunResult {
  std::vector<OutputRecord> outputs;
  std::vector<VioOutcome> vio_outcomes;

  // RMS over outputs with from <= t < to (seconds of IMU time) and status OK.
  double positionRms(double from, double to) const;
  double attitudeRmsDeg(double from, double to) const;
  double velocityRms(double from, double to) const;
  double maxPositionError(double from, double to) const;
  int countStatus(EstimatorStatus status) const;
};

// Called for every pose before it is handed over; return false to drop it. It may edit the pose.
using VioFilter = std::function<bool(VioPose&)>;

RunResult runEstimator(Estimator& estimator, const SensorSimulator& sensors, const std::vector<SensorEvent>& events,
                       const VioFilter& vio_filter = {});

}  // namespace sdlqr::estimator::test
