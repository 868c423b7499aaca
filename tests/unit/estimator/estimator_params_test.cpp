#include <gtest/gtest.h>

#include <string>

#include "sdlqr/estimator/estimator_params.hpp"

#include "config_errors.hpp"

namespace sdlqr::estimator {
namespace {

EstimatorParams loadText(const std::string& text) { return testing::loadSectionText<EstimatorParams>(text, "estimator"); }

TEST(EstimatorParams, DefaultsAreValidAndMatchTheAgreedSensorModel) {
  const EstimatorParams p;
  EXPECT_TRUE(p.valid()) << p.invalidReason();
  EXPECT_EQ(p.gyro_noise_density, 5e-4);
  EXPECT_EQ(p.accel_noise_density, 4e-3);
  EXPECT_EQ(p.gyro_bias_random_walk, 2e-5);
  EXPECT_EQ(p.accel_bias_random_walk, 2e-4);
  // The simulator's accelerometer clips at 156.9 m/s^2: a reading there must count as clipped,
  // and no reading below its range may be rejected as corrupt.
  EXPECT_LT(p.accel_clip_level, 156.9);
  EXPECT_GT(p.accel_range, 156.9);
  EXPECT_EQ(p.output_rate, 250.0);
  EXPECT_EQ(p.outputPeriodUs(), 4000);
  EXPECT_GE(p.history_length, 0.15);
}

TEST(EstimatorParams, HistoryCapacityReachesHistoryLengthBack) {
  EstimatorParams p;
  p.history_length = 0.2;
  // 0.2 s / 4 ms = 50 periods back from the newest: 51 states, plus one before the oldest time.
  EXPECT_EQ(p.historyCapacity(), 52);
  p.history_length = 0.15;
  p.output_rate = 200.0;
  EXPECT_EQ(p.historyCapacity(), 32);
}

TEST(EstimatorParams, LoadsEveryKey) {
  const EstimatorParams p = loadText(
      "{gyro_noise_density: 1e-3, accel_noise_density: 2e-2, gyro_bias_random_walk: 3e-5,"
      " accel_bias_random_walk: 4e-4, gyro_range: 30, accel_range: 100, accel_clip_level: 95, clip_velocity_std: 0.5,"
      " initial_velocity_std: 0.5,"
      " initial_gyro_bias_std: 0.03, initial_accel_bias_std: 0.2, vio_position_std: 0.02, vio_attitude_std: 0.01,"
      " output_rate: 200, history_length: 0.3, vio_timeout: 0.4, reinit_after: 1.5, gate_chi2: 20, vio_reset_after: 0.25,"
      " quaternion_norm_tolerance: 0.02, imu_max_gap: 0.05, imu_time_reset_count: 10, gravity: 9.8}");
  EXPECT_EQ(p.gyro_noise_density, 1e-3);
  EXPECT_EQ(p.accel_noise_density, 2e-2);
  EXPECT_EQ(p.gyro_bias_random_walk, 3e-5);
  EXPECT_EQ(p.accel_bias_random_walk, 4e-4);
  EXPECT_EQ(p.gyro_range, 30.0);
  EXPECT_EQ(p.accel_range, 100.0);
  EXPECT_EQ(p.accel_clip_level, 95.0);
  EXPECT_EQ(p.clip_velocity_std, 0.5);
  EXPECT_EQ(p.initial_velocity_std, 0.5);
  EXPECT_EQ(p.initial_gyro_bias_std, 0.03);
  EXPECT_EQ(p.initial_accel_bias_std, 0.2);
  EXPECT_EQ(p.vio_position_std, 0.02);
  EXPECT_EQ(p.vio_attitude_std, 0.01);
  EXPECT_EQ(p.output_rate, 200.0);
  EXPECT_EQ(p.history_length, 0.3);
  EXPECT_EQ(p.vio_timeout, 0.4);
  EXPECT_EQ(p.reinit_after, 1.5);
  EXPECT_EQ(p.gate_chi2, 20.0);
  EXPECT_EQ(p.vio_reset_after, 0.25);
  EXPECT_EQ(p.quaternion_norm_tolerance, 0.02);
  EXPECT_EQ(p.imu_max_gap, 0.05);
  EXPECT_EQ(p.imu_time_reset_count, 10);
  EXPECT_EQ(p.gravity, 9.8);
}

TEST(EstimatorParams, BadValuesNameTheirKey) {
  testing::expectKeysBlamed(loadText, {
      {"{gyro_noise_density: 0}", "estimator.gyro_noise_density"},
      {"{accel_bias_random_walk: -1}", "estimator.accel_bias_random_walk"},
      {"{output_rate: 300}", "estimator.output_rate"},  // 3333.3 us is not whole
      {"{output_rate: 0}", "estimator.output_rate"},
      {"{history_length: 0.1}", "estimator.history_length"},  // shorter than VIO latency + margin
      {"{vio_timeout: 0.5, reinit_after: 0.4}", "estimator.reinit_after"},
      {"{gate_chi2: 0}", "estimator.gate_chi2"},
      {"{accel_range: 100, accel_clip_level: 120}", "estimator.accel_clip_level"},  // never seen
      {"{clip_velocity_std: 0}", "estimator.clip_velocity_std"},
      {"{reinit_after: 1.0, vio_reset_after: 1.0}", "estimator.vio_reset_after"},
      {"{vio_reset_after: -0.3}", "estimator.vio_reset_after"},
      {"{quaternion_norm_tolerance: 0.7}", "estimator.quaternion_norm_tolerance"},
      {"{imu_time_reset_count: 0}", "estimator.imu_time_reset_count"},
      {"{gravity: .nan}", "estimator.gravity"},
      {"{output_rate: fast}", "estimator.output_rate"},
      {"{history_lenght: 0.2}", "estimator.history_lenght"},
  });
}

TEST(EstimatorParams, TheVehicleFileSectionLoads) {
  const ConfigReader root(loadYamlFile(std::string(SDLQR_SOURCE_DIR) + "/config/quad255.yaml"), "");
  ASSERT_TRUE(root.has("estimator"));
  const EstimatorParams p = EstimatorParams::load(root.child("estimator"));
  EXPECT_TRUE(p.valid());
  EXPECT_EQ(p.outputPeriodUs(), 4000);
}

}  // namespace
}  // namespace sdlqr::estimator
