#pragma once
// Settings of the estimator-fusion emulator (section `estimator:` of the vehicle file). The noise
// defaults are the ones the simulator is agreed to produce; the timing defaults fit VIO at 30 Hz
// with 30-50 ms latency.

#include <cstdint>
#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/model.hpp"

namespace sdlqr::estimator {

struct EstimatorParams {
  // IMU model (continuous-time densities; per-sample std = density * sqrt(sample rate)).
  double gyro_noise_density = 5e-4;      // [rad/s/sqrt(Hz)]
  double accel_noise_density = 4e-3;     // [m/s^2/sqrt(Hz)]
  double gyro_bias_random_walk = 2e-5;   // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk = 2e-4;  // [m/s^3/sqrt(Hz)]
  // Beyond the sensor's own range (2000 deg/s, 16 g, where the simulator clips) a reading is corrupt.
  double gyro_range = 35.0;              // [rad/s] per axis
  double accel_range = 160.0;            // [m/s^2] per axis
  // A reading at or beyond the clip level (per axis) is the sensor saturating: the sample's delta
  // velocity then misses an unknown part of the specific force (a touchdown's impulse), which the
  // filter covers by adding clip_velocity_std^2 per clipped sample to the velocity variance. The
  // simulator's ground stops a 0.4 m/s descent within one 1 ms step: one sample reads 16 g and
  // 0.25 m/s go missing; much more than ~0.3 m/s lets VIO noise shortly after the impact kick
  // the velocity, much less leaves the miss to be found by the gated-pose reset.
  double accel_clip_level = 149.0;       // [m/s^2] 0.95 x the simulator's 16 g range (156.9)
  double clip_velocity_std = 0.3;        // [m/s] per clipped sample along the clipped body axis

  // Initial uncertainty; position and attitude start with the first pose's own std.
  double initial_velocity_std = 1.0;     // [m/s] velocity starts at zero: covers a restart mid-flight
  double initial_gyro_bias_std = 0.02;   // [rad/s] per axis
  double initial_accel_bias_std = 0.1;   // [m/s^2] per axis

  // VIO measurement noise used when a pose reports a std of 0 (unknown).
  double vio_position_std = 0.01;        // [m] per axis
  double vio_attitude_std = 0.008;       // [rad] per axis

  double output_rate = 250.0;            // [Hz] propagation and STATE_EST rate on the IMU-time grid
  double history_length = 0.2;           // [s] how far back a VIO capture time may lie (>= max VIO latency)
  double vio_timeout = 0.5;              // [s] no pose fused for this long: status VIO_TIMEOUT
  double reinit_after = 2.0;             // [s] no pose fused for this long: the next pose re-initialises
  double gate_chi2 = 28.0;               // [-] Mahalanobis^2 gate on the 6-dof pose innovation (chi2 6 dof, p ~ 1e-4)
  // Gated poses that agree with one another (each one's innovation within gate_chi2 of the
  // previous one's) for this long mean the filter, not the VIO, is wrong: reset to the VIO.
  double vio_reset_after = 0.3;          // [s] from the first to the newest pose of such a run
  double quaternion_norm_tolerance = 0.05;  // [-] | ||q|| - 1 | beyond this rejects a pose (as common/validate)
  double imu_max_gap = 0.1;              // [s] a larger step between IMU samples is rejected
  int imu_time_reset_count = 100;        // [samples] this many timing rejects in a row: restart on the new clock
  double gravity = kDefaultGravity;      // [m/s^2]

  // The output period in microseconds; valid() guarantees 1e6 / output_rate is a whole number.
  int64_t outputPeriodUs() const;
  // Entries the history buffer needs to reach history_length back from the newest state.
  int historyCapacity() const;

  static EstimatorParams load(const ConfigReader& estimator);
  // Empty when valid, else "key: reason" for the first violation found.
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr::estimator
