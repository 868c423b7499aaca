// SimParams: defaults are the agreed ones, the repository's vehicle file loads, bad values name their key.
#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/sim/sim_params.hpp"

#include "config_errors.hpp"

namespace sdlqr::sim {
namespace {

SimParams loadText(const std::string& text) { return testing::loadSectionText<SimParams>(text, "sim"); }

TEST(SimParams, DefaultsAreTheAgreedSensorModelAndValid) {
  const SimParams p;
  EXPECT_TRUE(p.valid()) << p.invalidReason();
  EXPECT_EQ(p.physics_rate_hz, 1000);
  EXPECT_EQ(p.imu.rate_hz, 1000);
  EXPECT_EQ(p.truth_rate_hz, 250);
  EXPECT_EQ(p.vio.rate_hz, 30);
  EXPECT_EQ(p.imu.gyro_noise_density, 5e-4);
  EXPECT_EQ(p.imu.accel_noise_density, 4e-3);
  EXPECT_EQ(p.imu.gyro_bias_random_walk, 2e-5);
  EXPECT_EQ(p.imu.accel_bias_random_walk, 2e-4);
  EXPECT_EQ(p.imu.gyro_bias_initial_max, 0.02);
  EXPECT_EQ(p.imu.accel_bias_initial_max, 0.1);
  EXPECT_EQ(p.vio.latency_min_s, 0.030);
  EXPECT_EQ(p.vio.latency_max_s, 0.050);
  EXPECT_EQ(p.vio.position_std, 0.01);
  EXPECT_EQ(p.vio.attitude_std, 0.008);
  EXPECT_EQ(p.battery.calibration_charge, 0.7);
  EXPECT_EQ(p.gravity, 9.81);
  EXPECT_EQ(p.physicsPeriodUs(), 1000);
}

TEST(SimParams, RepositoryVehicleFileMatchesTheDefaults) {
  const YAML::Node root = loadYamlFile(std::string(SDLQR_SOURCE_DIR) + "/config/quad255.yaml");
  const ConfigReader config(root, "");
  const SimParams file = SimParams::load(config.child("sim"));
  const SimParams code;
  EXPECT_EQ(file.imu.gyro_noise_density, code.imu.gyro_noise_density);
  EXPECT_EQ(file.imu.accel_noise_density, code.imu.accel_noise_density);
  EXPECT_EQ(file.imu.gyro_bias_random_walk, code.imu.gyro_bias_random_walk);
  EXPECT_EQ(file.imu.accel_bias_random_walk, code.imu.accel_bias_random_walk);
  EXPECT_EQ(file.imu.gyro_range, code.imu.gyro_range);
  EXPECT_EQ(file.imu.accel_range, code.imu.accel_range);
  EXPECT_EQ(file.physics_rate_hz, code.physics_rate_hz);
  EXPECT_EQ(file.truth_rate_hz, code.truth_rate_hz);
  EXPECT_EQ(file.vio.latency_min_s, code.vio.latency_min_s);
  EXPECT_EQ(file.vio.latency_max_s, code.vio.latency_max_s);
  EXPECT_EQ(file.vio.position_std, code.vio.position_std);
  EXPECT_EQ(file.vio.attitude_std, code.vio.attitude_std);
  EXPECT_EQ(file.battery.capacity_mah, code.battery.capacity_mah);
  EXPECT_EQ(file.battery.initial_charge, code.battery.initial_charge);
  EXPECT_EQ(file.ground.crash_speed, code.ground.crash_speed);
  EXPECT_EQ(file.seed, code.seed);
  EXPECT_NO_THROW(VehicleParams::load(config.child("vehicle")));
}

TEST(SimParams, LoadsNestedSections) {
  const SimParams p = loadText(
      "{physics_rate_hz: 2000, truth_rate_hz: 100, imu: {rate_hz: 500, gyro_noise_density: 1e-3},"
      " vio: {rate_hz: 20, latency_min_s: 0.01, latency_max_s: 0.02}, battery: {enabled: false, cell_count: 4},"
      " ground: {crash_speed: 3.0}, disturbance: {max_force: 10}, initial_position: [1, 2, 0], initial_yaw: 0.5,"
      " seed: 77, gravity: 9.8}");
  EXPECT_EQ(p.physics_rate_hz, 2000);
  EXPECT_EQ(p.physicsPeriodUs(), 500);
  EXPECT_EQ(p.imu.rate_hz, 500);
  EXPECT_EQ(p.imu.gyro_noise_density, 1e-3);
  EXPECT_EQ(p.vio.rate_hz, 20);
  EXPECT_FALSE(p.battery.enabled);
  EXPECT_EQ(p.battery.cell_count, 4);
  EXPECT_EQ(p.ground.crash_speed, 3.0);
  EXPECT_EQ(p.disturbance.max_force, 10.0);
  EXPECT_EQ(p.initial_position.y(), 2.0);
  EXPECT_EQ(p.seed, 77);
}

TEST(SimParams, EveryInvalidValueNamesItsKey) {
  testing::expectKeysBlamed(loadText, {
      {"{bogus: 1}", "sim.bogus"},
      {"{imu: {gyro_noise: 1}}", "sim.imu.gyro_noise"},
      {"{physics_rate_hz: 3000}", "sim.physics_rate_hz"},  // 333.3 us period
      {"{physics_rate_hz: 500}", "sim.physics_rate_hz"},  // RK4 at >= 1 kHz
      {"{imu: {accel_range: 15}}", "sim.imu.accel_range"},
      {"{imu: {gyro_range: 0}}", "sim.imu.gyro_range"},
      {"{truth_rate_hz: 300}", "sim.truth_rate_hz"},
      {"{imu: {rate_hz: 300}}", "sim.imu.rate_hz"},
      {"{imu: {accel_noise_density: -1}}", "sim.imu.accel_noise_density"},
      {"{vio: {rate_hz: 0}}", "sim.vio.rate_hz"},
      {"{vio: {latency_min_s: 0.06}}", "sim.vio.latency_max_s"},
      {"{vio: {latency_min_s: 0.0, latency_max_s: 0.04}}", "sim.vio.latency_max_s"},  // reorders
      {"{vio: {rate_hz: 400, latency_min_s: 0.05, latency_max_s: 0.05}}", "sim.vio.latency_max_s"},
      {"{vio: {position_std: .nan}}", "sim.vio.position_std"},
      {"{battery: {initial_charge: 1.2}}", "sim.battery.initial_charge"},
      {"{battery: {cell_count: 0}}", "sim.battery.cell_count"},
      {"{battery: {capacity_mah: 0}}", "sim.battery.capacity_mah"},
      {"{battery: {enabled: maybe}}", "sim.battery.enabled"},
      {"{ground: {crash_speed: 0}}", "sim.ground.crash_speed"},
      {"{ground: {crash_tilt: 4}}", "sim.ground.crash_tilt"},
      {"{disturbance: {max_force: -1}}", "sim.disturbance.max_force"},
      {"{initial_position: [0, 0, -1]}", "sim.initial_position"},
      {"{initial_position: [0, 0]}", "sim.initial_position"},
      {"{seed: -3}", "sim.seed"},
      {"{gravity: 0}", "sim.gravity"},
      {"{imu: 5}", "sim.imu"},
  });
}

}  // namespace
}  // namespace sdlqr::sim
