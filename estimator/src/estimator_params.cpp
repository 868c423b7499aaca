#include "sdlqr/estimator/estimator_params.hpp"

#include <cmath>

namespace sdlqr::estimator {

int64_t EstimatorParams::outputPeriodUs() const { return static_cast<int64_t>(std::llround(1e6 / output_rate)); }

int EstimatorParams::historyCapacity() const {
  const double period = static_cast<double>(outputPeriodUs()) * 1e-6;
  // States at T, T - period, ..., back to T - history_length, plus the one just before it so a
  // capture time exactly history_length old still has a state at or before it.
  return static_cast<int>(std::ceil(history_length / period - 1e-9)) + 2;
}

EstimatorParams::EstimatorParams() { declaration().setDefaults(*this); }

const ParamTable<EstimatorParams>& EstimatorParams::declaration() {
  static const ParamTable<EstimatorParams> table = [] {
    using P = EstimatorParams;
    ParamTable<P> t("error-state EKF, IMU + delayed VIO (sdlqr-estimator)");
    const Range positive = Range::above(0.0);
    t.number("gyro_noise_density", &P::gyro_noise_density, 5e-4, "rad/s/sqrt(Hz)", positive,
             "white gyro noise (per-sample std 0.016 rad/s at 1 kHz)");
    t.number("accel_noise_density", &P::accel_noise_density, 4e-3, "m/s^2/sqrt(Hz)", positive,
             "white accelerometer noise");
    t.number("gyro_bias_random_walk", &P::gyro_bias_random_walk, 2e-5, "rad/s^2/sqrt(Hz)", positive, "gyro bias drift");
    t.number("accel_bias_random_walk", &P::accel_bias_random_walk, 2e-4, "m/s^3/sqrt(Hz)", positive,
             "accelerometer bias drift");
    t.number("gyro_range", &P::gyro_range, 35.0, "rad/s", positive,
             "per axis; larger readings are rejected (sensor clips at 34.9)");
    t.number("accel_range", &P::accel_range, 160.0, "m/s^2", positive,
             "per axis; larger readings are rejected (sensor clips at 156.9)");
    t.number("accel_clip_level", &P::accel_clip_level, 149.0, "m/s^2", positive,
             "per axis; readings at or beyond count as clipped (0.95 x 156.9)");
    t.number("clip_velocity_std", &P::clip_velocity_std, 0.3, "m/s", positive,
             "velocity a clipped sample may have missed (a 0.4 m/s touchdown misses 0.25)");
    t.number("initial_velocity_std", &P::initial_velocity_std, 1.0, "m/s", positive,
             "velocity starts at zero (covers a restart mid-flight)");
    t.number("initial_gyro_bias_std", &P::initial_gyro_bias_std, 0.02, "rad/s", positive, "per axis");
    t.number("initial_accel_bias_std", &P::initial_accel_bias_std, 0.1, "m/s^2", positive, "per axis");
    t.number("vio_position_std", &P::vio_position_std, 0.01, "m", positive, "used when a pose reports position_std 0");
    t.number("vio_attitude_std", &P::vio_attitude_std, 0.008, "rad", positive, "used when a pose reports attitude_std 0");
    t.number("output_rate", &P::output_rate, 250.0, "Hz", Range::closed(1.0, 1000.0),
             "propagation and STATE_EST rate on the IMU-time grid");
    // 150 ms covers the 30-50 ms VIO latency of the simulator with margin for a late bus; 2 s bounds memory.
    t.number("history_length", &P::history_length, 0.2, "s", Range::closed(0.15, 2.0),
             "oldest accepted VIO capture time behind the newest state");
    t.number("vio_timeout", &P::vio_timeout, 0.5, "s", positive, "no pose fused for this long: status VIO_TIMEOUT");
    t.number("reinit_after", &P::reinit_after, 2.0, "s", positive,
             "no pose fused for this long: the next pose re-initialises");
    t.number("gate_chi2", &P::gate_chi2, 28.0, "-", positive, "Mahalanobis^2 gate, 6-dof pose innovation (chi2 p ~ 1e-4)");
    t.number("vio_reset_after", &P::vio_reset_after, 0.3, "s", positive,
             "gated poses agreeing with one another this long: reset to the VIO");
    t.number("quaternion_norm_tolerance", &P::quaternion_norm_tolerance, 0.05, "-", Range::open(0.0, 0.5),
             "reject a pose whose | ||q|| - 1 | exceeds this");
    t.number("imu_max_gap", &P::imu_max_gap, 0.1, "s", Range::openClosed(0.0, 1.0),
             "larger steps between IMU samples are rejected");
    t.integer("imu_time_reset_count", &P::imu_time_reset_count, 100, "samples", Range::atLeast(1),
              "timing rejects in a row that mean a new clock: start over");
    t.number("gravity", &P::gravity, kDefaultGravity, "m/s^2", positive, "gravity of the filter's model");
    // Above accel_range a reading is rejected, so a higher clip level could never be seen.
    t.check("accel_clip_level", [](const P& p) { return p.accel_clip_level <= p.accel_range; }, "must be <= accel_range");
    t.check("output_rate",
            [](const P& p) {
              const double period_us = 1e6 / p.output_rate;
              return std::abs(period_us - std::round(period_us)) <= 1e-6;
            },
            "1e6 / output_rate must be a whole number of microseconds (e.g. 250, 200, 500)");
    t.check("history_length", [](const P& p) { return p.history_length * p.output_rate >= 2.0; },
            "must span at least two output periods");
    t.check("reinit_after", [](const P& p) { return p.reinit_after > p.vio_timeout; }, "must be > vio_timeout");
    // Past reinit_after the next pose re-initialises anyway; a reset must come before that.
    t.check("vio_reset_after", [](const P& p) { return p.vio_reset_after < p.reinit_after; }, "must be < reinit_after");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::estimator
