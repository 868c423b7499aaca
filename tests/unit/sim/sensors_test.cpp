// IMU and VIO: physically right readings, the agreed noise statistics, bias drift, VIO timing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>
#include <vector>

#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

using namespace test;  // sim_test_support.hpp

// Mean and standard deviation per axis of a series of 3-vectors.
struct Stats {
  Vec3 mean = Vec3::Zero();
  Vec3 std = Vec3::Zero();
};

Stats statsOf(const std::vector<Vec3>& samples) {
  Stats s;
  for (const Vec3& x : samples) s.mean += x;
  s.mean /= static_cast<double>(samples.size());
  for (const Vec3& x : samples) s.std += (x - s.mean).cwiseAbs2();
  s.std = (s.std / static_cast<double>(samples.size() - 1)).cwiseSqrt();
  return s;
}

struct ImuResiduals {
  std::vector<Vec3> gyro;   // reading minus true bias
  std::vector<Vec3> accel;
};

ImuResiduals collectImu(Simulator& sim, double seconds) {
  ImuResiduals r;
  for (int64_t i = stepsFor(sim, seconds); i > 0; --i) {
    const StepOutput out = sim.step();
    if (!out.imu) continue;
    r.gyro.push_back(out.imu->gyro - sim.imu().gyroBias());
    r.accel.push_back(out.imu->accel - sim.imu().accelBias());
  }
  return r;
}

TEST(Imu, AtRestOnTheGroundReadsPlusGOnBodyZWithTheAgreedNoise) {
  // GIVEN a landed, yawed vehicle with the default (agreed) IMU noise
  SimParams p;
  p.initial_yaw = 2.0;
  Simulator sim(VehicleParams(), p);
  // WHEN 20 s of samples are taken
  const ImuResiduals r = collectImu(sim, 20.0);
  ASSERT_EQ(r.accel.size(), 20000u);
  const Stats accel = statsOf(r.accel);
  const Stats gyro = statsOf(r.gyro);
  const double accel_std = p.imu.accel_noise_density * std::sqrt(1000.0);
  const double gyro_std = p.imu.gyro_noise_density * std::sqrt(1000.0);
  std::cout << "accel mean " << accel.mean.transpose() << " std " << accel.std.transpose() << " (expected "
            << accel_std << ")\ngyro mean " << gyro.mean.transpose() << " std " << gyro.std.transpose()
            << " (expected " << gyro_std << ")\n";
  // THEN the specific force is +g along body z, bias aside, within 5 standard errors
  const double accel_se = 5.0 * accel_std / std::sqrt(20000.0);
  const double gyro_se = 5.0 * gyro_std / std::sqrt(20000.0);
  EXPECT_NEAR(accel.mean.x(), 0.0, accel_se);
  EXPECT_NEAR(accel.mean.y(), 0.0, accel_se);
  EXPECT_NEAR(accel.mean.z(), p.gravity, accel_se);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(gyro.mean[i], 0.0, gyro_se);
    // The sample std of 20000 normals is within 3 % of the truth with overwhelming probability.
    EXPECT_NEAR(accel.std[i], accel_std, 0.03 * accel_std);
    EXPECT_NEAR(gyro.std[i], gyro_std, 0.03 * gyro_std);
  }
}

TEST(Imu, ReadsSpecificForceInFreeFallAndRotationInSpin) {
  // GIVEN a tumbling vehicle falling with the motors off and a noiseless IMU
  SimParams p = idealParams();
  p.imu = ImuParams{};
  p.imu.gyro_noise_density = p.imu.accel_noise_density = 0.0;
  p.imu.gyro_bias_random_walk = p.imu.accel_bias_random_walk = 0.0;
  p.imu.gyro_bias_initial_max = p.imu.accel_bias_initial_max = 0.0;
  Simulator sim(VehicleParams(), p);
  const Vec3 spin(0.3, -0.2, 1.0);
  sim.setBodyState(airborne(Vec3(0, 0, 50.0), Vec3::Zero(), quat::exp(Vec3(0.4, 0.1, 0.0)), spin));
  StepOutput out;
  for (int i = 0; i < 500; ++i) out = sim.step();
  ASSERT_TRUE(out.imu);
  // THEN a free-falling accelerometer reads zero and the gyro reads the body rate
  EXPECT_LT(out.imu->accel.norm(), 1e-9);
  EXPECT_LT((out.imu->gyro - sim.body().body_rate).norm(), 1e-15);
  EXPECT_GT(sim.body().body_rate.norm(), 0.5);  // it really spins (Euler's equations move it)
}

TEST(Imu, HoveringReadsThrustOverMassOnBodyZ) {
  SimParams p = idealParams();
  Simulator sim(VehicleParams(), p);
  const VehicleParams v;
  sim.setBodyState(airborne(Vec3(0, 0, 1.0), Vec3::Zero(), quat::fromYaw(0.5)), hoverThrust(v));
  sim.setMotorCommand(armed(hoverThrust(v)));
  const ImuResiduals r = collectImu(sim, 5.0);
  const Stats accel = statsOf(r.accel);
  EXPECT_NEAR(accel.mean.z(), p.gravity, 0.01);
  EXPECT_NEAR(accel.mean.x(), 0.0, 0.01);
}

TEST(Imu, BiasesStartWithinTheirRangeAndWalkAtTheConfiguredRate) {
  const SimParams p;
  std::vector<Vec3> gyro_steps, accel_steps;
  for (uint64_t seed = 1; seed <= 5; ++seed) {
    Simulator sim(VehicleParams(), p, seed);
    EXPECT_LE(sim.imu().gyroBias().cwiseAbs().maxCoeff(), p.imu.gyro_bias_initial_max);
    EXPECT_LE(sim.imu().accelBias().cwiseAbs().maxCoeff(), p.imu.accel_bias_initial_max);
    EXPECT_GT(sim.imu().gyroBias().norm(), 0.0);
    Vec3 gyro_bias = sim.imu().gyroBias();
    Vec3 accel_bias = sim.imu().accelBias();
    for (int i = 0; i < 40000; ++i) {
      if (!sim.step().imu) continue;
      gyro_steps.push_back(sim.imu().gyroBias() - gyro_bias);
      accel_steps.push_back(sim.imu().accelBias() - accel_bias);
      gyro_bias = sim.imu().gyroBias();
      accel_bias = sim.imu().accelBias();
    }
  }
  // Random-walk increments over one IMU period have std = walk density x sqrt(period).
  const Stats gyro = statsOf(gyro_steps);
  const Stats accel = statsOf(accel_steps);
  const double gyro_expected = p.imu.gyro_bias_random_walk * std::sqrt(1e-3);
  const double accel_expected = p.imu.accel_bias_random_walk * std::sqrt(1e-3);
  std::cout << "bias increment std: gyro " << gyro.std.transpose() << " (expected " << gyro_expected << "), accel "
            << accel.std.transpose() << " (expected " << accel_expected << ")\n";
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(gyro.std[i], gyro_expected, 0.02 * gyro_expected);
    EXPECT_NEAR(accel.std[i], accel_expected, 0.02 * accel_expected);
  }
}

TEST(Imu, ReadingsFollowTheDriftingBias) {
  // With a large walk, a window's mean reading tracks the true bias of that window.
  SimParams p;
  p.imu.accel_bias_random_walk = 0.05;
  Simulator sim(VehicleParams(), p);
  Vec3 first_bias = sim.imu().accelBias();
  for (int window = 0; window < 5; ++window) {
    Vec3 reading_sum = Vec3::Zero(), bias_sum = Vec3::Zero();
    for (int i = 0; i < 2000; ++i) {
      const StepOutput out = sim.step();
      reading_sum += out.imu->accel - Vec3(0, 0, p.gravity);
      bias_sum += sim.imu().accelBias();
    }
    EXPECT_LT((reading_sum - bias_sum).norm() / 2000.0, 5.0 * 0.1265 / std::sqrt(2000.0));
  }
  EXPECT_GT((sim.imu().accelBias() - first_bias).norm(), 0.01);  // it did drift
}

struct VioRecord {
  VioPose pose;
  int64_t received_utime;
};

TEST(Vio, ThirtyHertzDelayedThirtyToFiftyMsWithThePoseOfCaptureTime) {
  // GIVEN a vehicle falling fast and spinning, so a pose from the wrong instant would be far off
  SimParams p;
  p.battery.enabled = false;
  Simulator sim(VehicleParams(), p);
  sim.setBodyState(airborne(Vec3(0, 0, 1000.0), Vec3(3.0, 0.0, 5.0), identityQuat(), Vec3(0.0, 0.0, 2.0)));
  std::map<int64_t, BodyState> truth_at;
  std::vector<VioRecord> poses;
  for (int64_t i = stepsFor(sim, 10.0); i > 0; --i) {
    const StepOutput out = sim.step();
    truth_at[sim.utime()] = sim.body();
    if (out.vio) poses.push_back({*out.vio, sim.utime()});
  }
  // THEN 30 per second
  std::cout << "VIO poses in 10 s: " << poses.size() << "\n";
  EXPECT_NEAR(static_cast<double>(poses.size()), 300.0, 2.0);
  std::vector<Vec3> position_error, attitude_error;
  double latency_min = 1e9, latency_max = 0.0, latency_sum = 0.0;
  for (size_t i = 0; i < poses.size(); ++i) {
    const VioPose& v = poses[i].pose;
    EXPECT_EQ(v.seq, static_cast<int64_t>(i));
    EXPECT_EQ(v.publish_utime, poses[i].received_utime);  // published exactly when due
    const double latency = (v.publish_utime - v.utime) * 1e-6;
    latency_min = std::min(latency_min, latency);
    latency_max = std::max(latency_max, latency);
    latency_sum += latency;
    EXPECT_GE(latency, 0.030 - 1e-9);
    EXPECT_LE(latency, 0.050 + 1e-9);
    if (i > 0) {
      const int64_t interval = v.utime - poses[i - 1].pose.utime;
      EXPECT_TRUE(interval == 33000 || interval == 34000) << interval;
    }
    ASSERT_TRUE(truth_at.count(v.utime));
    const BodyState& truth = truth_at[v.utime];
    position_error.push_back(v.position - truth.position);
    attitude_error.push_back(quat::boxMinus(v.orientation, truth.orientation));
    EXPECT_DOUBLE_EQ(v.position_std, p.vio.position_std);
    EXPECT_DOUBLE_EQ(v.attitude_std, p.vio.attitude_std);
  }
  const Stats pos = statsOf(position_error);
  const Stats att = statsOf(attitude_error);
  std::cout << "VIO latency " << latency_min << ".." << latency_max << " s, mean " << latency_sum / poses.size()
            << "; position error std " << pos.std.transpose() << ", attitude error std " << att.std.transpose()
            << "\n";
  EXPECT_NEAR(latency_sum / poses.size(), 0.040, 0.002);
  EXPECT_LT(latency_min, 0.032);
  EXPECT_GT(latency_max, 0.048);
  // AND the pose is the truth at capture time plus the configured noise (300 samples: +-20 %)
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(pos.std[i], p.vio.position_std, 0.2 * p.vio.position_std);
    EXPECT_NEAR(att.std[i], p.vio.attitude_std, 0.2 * p.vio.attitude_std);
    EXPECT_NEAR(pos.mean[i], 0.0, 4.0 * p.vio.position_std / std::sqrt(300.0));
  }
}

}  // namespace
}  // namespace sdlqr::sim

namespace sdlqr::sim {
namespace {

TEST(Imu, TouchdownSpikeClipsAtTheSensorRange) {
  // GIVEN a vehicle dropped from 0.5 m: the ground stops 3.1 m/s within one step
  SimParams p = test::idealParams();
  p.initial_position = Vec3(0, 0, 0.5);
  Simulator sim(VehicleParams(), p);
  double peak = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const StepOutput out = sim.step();
    peak = std::max(peak, out.imu->accel.cwiseAbs().maxCoeff());
    ASSERT_LE(out.imu->accel.cwiseAbs().maxCoeff(), p.imu.accel_range);
  }
  // THEN the impact shows as a reading at full scale, not as an impossible value
  std::cout << "true impact deceleration ~" << std::sqrt(2 * 9.81 * 0.5) / sim.period() << " m/s^2, peak reading "
            << peak << "\n";
  EXPECT_EQ(peak, p.imu.accel_range);
  EXPECT_TRUE(sim.onGround());
}

}  // namespace
}  // namespace sdlqr::sim
