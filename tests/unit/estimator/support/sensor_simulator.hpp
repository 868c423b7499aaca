#pragma once
// Deterministic sensor simulator for the estimator tests (PX4 EKF2 sensor_simulator style): IMU
// samples of a truth trajectory with seeded white noise and random-walk biases, clipped at the
// sensor's range like sdlqr-sim's, and VIO poses at 30 Hz with seeded noise, delivered after a
// random 30-50 ms latency. The output is one event list in arrival order, generated up front so
// the estimator under test runs alone.

#include <cstdint>
#include <functional>
#include <random>
#include <utility>
#include <vector>

#include "analytic_trajectory.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::estimator::test {

struct SensorSpec {
  double imu_rate = 1000.0;               // [Hz]
  double gyro_noise_density = 5e-4;       // [rad/s/sqrt(Hz)]
  double accel_noise_density = 4e-3;      // [m/s^2/sqrt(Hz)]
  double gyro_bias_random_walk = 2e-5;    // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk = 2e-4;   // [m/s^3/sqrt(Hz)]
  double gyro_range = 34.9;               // [rad/s] readings clip here per axis (the simulator's 2000 deg/s)
  double accel_range = 156.9;             // [m/s^2] readings clip here per axis (the simulator's 16 g)
  double gyro_bias_range = 0.02;          // [rad/s] initial bias uniform in +-range per axis
  double accel_bias_range = 0.1;          // [m/s^2]
  bool random_initial_bias = true;        // false: start from the two biases below
  Vec3 initial_gyro_bias = Vec3::Zero();  // [rad/s]
  Vec3 initial_accel_bias = Vec3::Zero(); // [m/s^2]
  double vio_rate = 30.0;                 // [Hz]
  double vio_latency_min = 0.030;         // [s]
  double vio_latency_max = 0.050;         // [s]
  double vio_position_std = 0.01;         // [m] per axis
  double vio_attitude_std = 0.008;        // [rad] per axis, rotation-vector noise
  int64_t start_utime = 0;                // [us] first IMU sample
  uint64_t seed = 1;
};

struct SensorEvent {
  enum class Kind { kImu, kVio };
  Kind kind = Kind::kImu;
  int64_t arrival_utime = 0;  // IMU: its sample time; VIO: its publish time
  ImuSample imu;
  VioPose vio;
};

// The truth at a time in seconds.
using TruthFunction = std::function<TruthSample(double)>;

class SensorSimulator {
 public:
  SensorSimulator(TruthFunction truth, const SensorSpec& spec);
  // Any trajectory with `TruthSample at(double t) const` (AnalyticTrajectory, LandingTrajectory).
  template <class Trajectory, class = decltype(std::declval<const Trajectory&>().at(0.0))>
  SensorSimulator(const Trajectory& trajectory, const SensorSpec& spec)
      : SensorSimulator(TruthFunction([trajectory](double t) { return trajectory.at(t); }), spec) {}

  // Every event of the first `duration` seconds, in arrival order (IMU before VIO on a tie: the
  // pose published at t says nothing about t itself).
  std::vector<SensorEvent> run(double duration);

  TruthSample truthAt(int64_t utime) const { return truth_(1e-6 * static_cast<double>(utime)); }
  // True biases at an IMU sample time produced by run().
  Vec3 gyroBiasAt(int64_t utime) const { return gyro_bias_[sampleIndex(utime)]; }
  Vec3 accelBiasAt(int64_t utime) const { return accel_bias_[sampleIndex(utime)]; }
  const SensorSpec& spec() const { return spec_; }

 private:
  size_t sampleIndex(int64_t utime) const;

  TruthFunction truth_;
  SensorSpec spec_;
  std::mt19937_64 rng_;
  std::vector<Vec3> gyro_bias_;
  std::vector<Vec3> accel_bias_;
};

// One IMU sample of `truth` with the given biases and no noise.
ImuSample idealImu(const TruthSample& truth, int64_t utime, int64_t seq, const Vec3& gyro_bias = Vec3::Zero(),
                   const Vec3& accel_bias = Vec3::Zero());

}  // namespace sdlqr::estimator::test
