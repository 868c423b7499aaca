#include <gtest/gtest.h>

#include <iostream>
#include <vector>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/estimator/imu_downsampler.hpp"

namespace sdlqr::estimator {
namespace {

std::vector<ImuWindow> feed(ImuDownsampler& downsampler, const std::vector<ImuSample>& samples) {
  std::vector<ImuWindow> windows;
  for (const ImuSample& s : samples) downsampler.add(s, [&](const ImuWindow& w) { windows.push_back(w); });
  return windows;
}

ImuSample sampleAt(int64_t utime, const Vec3& gyro, const Vec3& accel, int64_t seq = 0) {
  ImuSample s;
  s.utime = utime;
  s.seq = seq;
  s.gyro = gyro;
  s.accel = accel;
  return s;
}

TEST(ImuDownsampler, ClosesOneWindowPerPeriodOnTheGrid) {
  // GIVEN 1 kHz samples from t = 0
  ImuDownsampler downsampler(4000);
  std::vector<ImuSample> samples;
  for (int64_t k = 0; k <= 40; ++k) samples.push_back(sampleAt(1000 * k, Vec3::Zero(), Vec3(0, 0, 9.81), k));
  // WHEN they are added
  const auto windows = feed(downsampler, samples);
  // THEN every fourth sample closes a 4 ms window ending on a multiple of 4 ms
  ASSERT_EQ(windows.size(), 10u);
  for (size_t i = 0; i < windows.size(); ++i) {
    EXPECT_EQ(windows[i].end_utime, 4000 * static_cast<int64_t>(i + 1));
    EXPECT_EQ(windows[i].last_imu_seq, 4 * static_cast<int64_t>(i + 1));
    EXPECT_DOUBLE_EQ(windows[i].delta.dt, 0.004);
    EXPECT_NEAR(windows[i].delta.delta_velocity.z(), 9.81 * 0.004, 1e-15);
  }
}

TEST(ImuDownsampler, ConstantRotationAndBodyForceIntegrateToTheExactDeltas) {
  // GIVEN a body turning at a constant rate with a constant body-frame specific force
  const Vec3 rate(0.8, -1.5, 1.2);   // rad/s
  const Vec3 force(1.0, -2.0, 9.0);  // m/s^2
  ImuDownsampler downsampler(4000);
  std::vector<ImuSample> samples;
  for (int64_t k = 0; k <= 4; ++k) samples.push_back(sampleAt(1000 * k, rate, force));
  // WHEN one window is integrated
  const auto windows = feed(downsampler, samples);
  ASSERT_EQ(windows.size(), 1u);
  // THEN the delta angle is rate * T and the delta velocity matches the closed form
  // integral of Exp(rate t) force dt, evaluated here by fine quadrature
  const double period = 0.004;
  EXPECT_NEAR((windows[0].delta.delta_angle - rate * period).norm(), 0.0, 1e-12);
  Vec3 expected = Vec3::Zero();
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double t = (i + 0.5) * period / n;
    expected += quat::rotate(quat::exp(rate * t), force) * (period / n);
  }
  const double error = (windows[0].delta.delta_velocity - expected).norm();
  std::cout << "[ measured ] delta-velocity error with rotation (coning/sculling) " << error << " m/s\n";
  // Midpoint rule per 1 ms step: bound T h^2 |rate|^2 |force| / 24 = 6.7e-9 m/s.
  EXPECT_LT(error, 1e-8);
  // (without the rotation inside the window the error would be ~|rate| T |force| / 2)
  EXPECT_GT((force * period - expected).norm(), 1e-5);
}

TEST(ImuDownsampler, LinearlyVaryingRatesAreIntegratedExactlyAcrossOffGridSamples) {
  // GIVEN samples 1.3 ms apart, off the grid, of a rate and force that grow linearly in time
  // (about the z axis only, so the rotation commutes and the integral has a closed form)
  auto rate_at = [](double t) { return Vec3(0.0, 0.0, 2.0 + 50.0 * t); };
  auto force_at = [](double t) { return Vec3(0.0, 0.0, 9.0 + 100.0 * t); };
  ImuDownsampler downsampler(4000);
  std::vector<ImuSample> samples;
  for (int64_t k = 0; k <= 20; ++k) {
    const int64_t utime = 2500 + 1300 * k;
    samples.push_back(sampleAt(utime, rate_at(utime * 1e-6), force_at(utime * 1e-6)));
  }
  // WHEN they are added
  const auto windows = feed(downsampler, samples);
  // THEN the windows tile time exactly: the first runs from the first sample to the next edge,
  // the rest are whole, and each holds the exact integral over its own span
  ASSERT_GE(windows.size(), 5u);
  EXPECT_EQ(windows[0].end_utime, 4000);
  EXPECT_NEAR(windows[0].delta.dt, 0.0015, 1e-15);
  for (size_t i = 1; i < windows.size(); ++i) {
    EXPECT_EQ(windows[i].end_utime - windows[i - 1].end_utime, 4000);
    EXPECT_NEAR(windows[i].delta.dt, 0.004, 1e-15);
    const double t1 = windows[i].end_utime * 1e-6, t0 = t1 - 0.004;
    const double angle = 2.0 * (t1 - t0) + 25.0 * (t1 * t1 - t0 * t0);
    const double velocity = 9.0 * (t1 - t0) + 50.0 * (t1 * t1 - t0 * t0);
    EXPECT_NEAR(windows[i].delta.delta_angle.z(), angle, 1e-13) << i;
    EXPECT_NEAR(windows[i].delta.delta_velocity.z(), velocity, 1e-13) << i;
  }
}

TEST(ImuDownsampler, AGapClosesEveryWindowItSpans) {
  ImuDownsampler downsampler(4000);
  const auto windows = feed(downsampler, {sampleAt(1000, Vec3::Zero(), Vec3::Zero()),
                                          sampleAt(2000, Vec3::Zero(), Vec3::Zero()),
                                          sampleAt(15000, Vec3::Zero(), Vec3::Zero(), 7)});
  ASSERT_EQ(windows.size(), 3u);  // ends 4000, 8000, 12000; the fourth is still open at 15000
  EXPECT_EQ(windows[2].end_utime, 12000);
  EXPECT_EQ(windows[2].last_imu_seq, 7);
  EXPECT_EQ(downsampler.lastSampleTime(), 15000);
}

TEST(ImuDownsampler, CountsClippedAccelerometerSamplesInTheWindowOfTheirTimestamp) {
  // GIVEN a 149 m/s^2 clip level and 1 kHz samples of which three reach it: one in the middle of
  // the first window (z), one exactly on the edge closing the second (x, negative), and one just
  // below the level
  ImuDownsampler downsampler(4000, 149.0);
  std::vector<ImuSample> samples;
  for (int64_t k = 0; k <= 12; ++k) {
    Vec3 accel(0.0, 0.0, 9.81);
    if (k == 2) accel.z() = 156.9;
    if (k == 8) accel.x() = -149.0;
    if (k == 10) accel.y() = 148.9;
    samples.push_back(sampleAt(1000 * k, Vec3::Zero(), accel, k));
  }
  // WHEN they are added
  const auto windows = feed(downsampler, samples);
  // THEN each clipped sample is counted once, on its own axis, in the window holding its
  // timestamp (a sample on an edge belongs to the window it closes); the near miss is not
  ASSERT_EQ(windows.size(), 3u);
  EXPECT_EQ(windows[0].delta.accel_clipped, Vec3(0.0, 0.0, 1.0));
  EXPECT_EQ(windows[1].delta.accel_clipped, Vec3(1.0, 0.0, 0.0));
  EXPECT_EQ(windows[2].delta.accel_clipped, Vec3::Zero());
  // AND without a clip level nothing counts
  ImuDownsampler unlimited(4000);
  for (const ImuWindow& w : feed(unlimited, samples)) EXPECT_EQ(w.delta.accel_clipped, Vec3::Zero());
}

}  // namespace
}  // namespace sdlqr::estimator
