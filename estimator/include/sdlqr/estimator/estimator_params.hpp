#pragma once
// Settings of the estimator-fusion emulator (section `estimator:` of the vehicle file). The noise
// defaults are the ones the simulator is agreed to produce; the timing defaults fit VIO at 30 Hz
// with 30-50 ms latency.

#include <cstdint>
#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/model.hpp"

namespace sdlqr::estimator {

// Each member is declared once (key, unit, default, range, help) in
// estimator/params/estimator_params.yaml (the rules across keys: estimator_params.cpp); the default
// constructor takes the defaults from there.
struct EstimatorParams : DeclaredParams<EstimatorParams> {
  // IMU model (continuous-time densities; per-sample std = density * sqrt(sample rate)).
  double gyro_noise_density;
  double accel_noise_density;
  double gyro_bias_random_walk;
  double accel_bias_random_walk;
  // Beyond the sensor's own range (2000 deg/s, 16 g, where the simulator clips) a reading is corrupt.
  double gyro_range;
  double accel_range;
  // A reading at or beyond the clip level (per axis) is the sensor saturating: the sample's delta
  // velocity then misses an unknown part of the specific force (a touchdown's impulse), which the
  // filter covers by adding clip_velocity_std^2 per clipped sample to the velocity variance. The
  // simulator's ground stops a 0.4 m/s descent within one 1 ms step: one sample reads 16 g and
  // 0.25 m/s go missing; much more than ~0.3 m/s lets VIO noise shortly after the impact kick
  // the velocity, much less leaves the miss to be found by the gated-pose reset.
  double accel_clip_level;
  double clip_velocity_std;

  // Initial uncertainty; position and attitude start with the first pose's own std.
  double initial_velocity_std;
  double initial_gyro_bias_std;
  double initial_accel_bias_std;

  // VIO measurement noise used when a pose reports a std of 0 (unknown).
  double vio_position_std;
  double vio_attitude_std;

  double output_rate;
  double history_length;
  double vio_timeout;
  double reinit_after;
  double gate_chi2;
  // Gated poses that agree with one another (each one's innovation within gate_chi2 of the
  // previous one's) for this long mean the filter, not the VIO, is wrong: reset to the VIO.
  double vio_reset_after;
  double quaternion_norm_tolerance;
  double imu_max_gap;
  int imu_time_reset_count;
  double gravity;

  EstimatorParams();
  static const ParamTable<EstimatorParams>& declaration();

  // The output period in microseconds; valid() guarantees 1e6 / output_rate is a whole number.
  int64_t outputPeriodUs() const;
  // Entries the history buffer needs to reach history_length back from the newest state.
  int historyCapacity() const;
};

}  // namespace sdlqr::estimator
