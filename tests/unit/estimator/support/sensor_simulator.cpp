#include "sensor_simulator.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::estimator::test {

namespace {

Vec3 gaussian(std::mt19937_64& rng, double std) {
  std::normal_distribution<double> n(0.0, std);
  const double x = n(rng), y = n(rng), z = n(rng);
  return Vec3(x, y, z);
}

Vec3 uniform(std::mt19937_64& rng, double range) {
  std::uniform_real_distribution<double> u(-range, range);
  const double x = u(rng), y = u(rng), z = u(rng);
  return Vec3(x, y, z);
}

}  // namespace

ImuSample idealImu(const TruthSample& truth, int64_t utime, int64_t seq, const Vec3& gyro_bias,
                   const Vec3& accel_bias) {
  ImuSample s;
  s.utime = utime;
  s.seq = seq;
  s.gyro = truth.body_rate + gyro_bias;
  s.accel = truth.specific_force + accel_bias;
  return s;
}

SensorSimulator::SensorSimulator(TruthFunction truth, const SensorSpec& spec)
    : truth_(std::move(truth)), spec_(spec), rng_(spec.seed) {}

size_t SensorSimulator::sampleIndex(int64_t utime) const {
  const double period_us = 1e6 / spec_.imu_rate;
  const auto index = static_cast<int64_t>(std::llround(static_cast<double>(utime - spec_.start_utime) / period_us));
  return static_cast<size_t>(std::clamp<int64_t>(index, 0, static_cast<int64_t>(gyro_bias_.size()) - 1));
}

std::vector<SensorEvent> SensorSimulator::run(double duration) {
  const double dt = 1.0 / spec_.imu_rate;
  const auto period_us = static_cast<int64_t>(std::llround(1e6 * dt));
  const auto samples = static_cast<int64_t>(std::floor(duration * spec_.imu_rate)) + 1;
  const double gyro_std = spec_.gyro_noise_density * std::sqrt(spec_.imu_rate);
  const double accel_std = spec_.accel_noise_density * std::sqrt(spec_.imu_rate);
  const double gyro_walk_std = spec_.gyro_bias_random_walk * std::sqrt(dt);
  const double accel_walk_std = spec_.accel_bias_random_walk * std::sqrt(dt);
  std::uniform_real_distribution<double> latency(spec_.vio_latency_min, spec_.vio_latency_max);

  Vec3 gyro_bias = spec_.initial_gyro_bias;
  Vec3 accel_bias = spec_.initial_accel_bias;
  if (spec_.random_initial_bias) {
    gyro_bias = uniform(rng_, spec_.gyro_bias_range);
    accel_bias = uniform(rng_, spec_.accel_bias_range);
  }
  gyro_bias_.clear();
  accel_bias_.clear();

  std::vector<SensorEvent> events;
  std::vector<SensorEvent> poses;
  int64_t vio_seq = 0;
  for (int64_t i = 0; i < samples; ++i) {
    const int64_t utime = spec_.start_utime + i * period_us;
    const TruthSample truth = truthAt(utime);
    gyro_bias_.push_back(gyro_bias);
    accel_bias_.push_back(accel_bias);

    SensorEvent imu;
    imu.kind = SensorEvent::Kind::kImu;
    imu.arrival_utime = utime;
    imu.imu = idealImu(truth, utime, i, gyro_bias, accel_bias);
    imu.imu.gyro = (imu.imu.gyro + gaussian(rng_, gyro_std)).cwiseMax(-spec_.gyro_range).cwiseMin(spec_.gyro_range);
    imu.imu.accel =
        (imu.imu.accel + gaussian(rng_, accel_std)).cwiseMax(-spec_.accel_range).cwiseMin(spec_.accel_range);
    events.push_back(imu);

    // A camera frame whenever a VIO period has elapsed, on the IMU clock like the simulator's.
    const double t = 1e-6 * static_cast<double>(utime - spec_.start_utime);
    if (std::floor(t * spec_.vio_rate + 1e-9) >= static_cast<double>(vio_seq)) {
      SensorEvent pose;
      pose.kind = SensorEvent::Kind::kVio;
      pose.vio.utime = utime;
      pose.vio.seq = vio_seq++;
      pose.vio.position = truth.position + gaussian(rng_, spec_.vio_position_std);
      pose.vio.orientation = quat::multiply(truth.orientation, quat::exp(gaussian(rng_, spec_.vio_attitude_std)));
      pose.vio.position_std = spec_.vio_position_std;
      pose.vio.attitude_std = spec_.vio_attitude_std;
      // Published on an IMU tick, as a simulator stepping at the IMU rate would.
      const auto delay_us = static_cast<int64_t>(std::llround(latency(rng_) * 1e6 / static_cast<double>(period_us))) *
                            period_us;
      pose.vio.publish_utime = utime + delay_us;
      pose.arrival_utime = pose.vio.publish_utime;
      poses.push_back(pose);
    }
    gyro_bias += gaussian(rng_, gyro_walk_std);
    accel_bias += gaussian(rng_, accel_walk_std);
  }
  const int64_t end_utime = events.back().arrival_utime;
  for (const SensorEvent& pose : poses) {
    if (pose.arrival_utime <= end_utime) events.push_back(pose);
  }
  std::stable_sort(events.begin(), events.end(), [](const SensorEvent& a, const SensorEvent& b) {
    if (a.arrival_utime != b.arrival_utime) return a.arrival_utime < b.arrival_utime;
    return a.kind == SensorEvent::Kind::kImu && b.kind == SensorEvent::Kind::kVio;
  });
  return events;
}

}  // namespace sdlqr::estimator::test
