// Rate PID: derivative on the measurement, anti-windup, integral reset when landed.

#include <gtest/gtest.h>

#include "sdlqr/lowlevel/rate_control.hpp"

namespace sdlqr::lowlevel {
namespace {

constexpr double kRateLoopDt = 0.001;

TEST(RateController, SetpointStepGivesNoDerivativeKick) {
  RateController pid;
  const Vec3 rate(0.1, -0.2, 0.05);
  for (int i = 0; i < 50; ++i) pid.update(rate, rate, kRateLoopDt, false);
  const Vec3 before = pid.update(rate, rate, kRateLoopDt, false);
  const Vec3 step(1.0, -1.0, 0.5);
  const Vec3 after = pid.update(rate, rate + step, kRateLoopDt, false);
  EXPECT_EQ(pid.status().derivative, Vec3::Zero());
  // Only the proportional term and one integration step react to a setpoint change.
  const RateControlParams& p = pid.params();
  const Vec3 expected = p.p.cwiseProduct(step) + p.i.cwiseProduct(step) * kRateLoopDt;
  EXPECT_TRUE((after - before).isApprox(expected, 1e-12)) << (after - before).transpose();
}

TEST(RateController, MeasurementChangeDrivesTheDerivative) {
  RateController pid;
  pid.update(Vec3::Zero(), Vec3::Zero(), kRateLoopDt, false);
  pid.update(Vec3(0.01, 0.0, 0.0), Vec3::Zero(), kRateLoopDt, false);  // 10 rad/s^2
  const double alpha = kRateLoopDt / (kRateLoopDt + 1.0 / (2.0 * M_PI * pid.params().d_cutoff_hz));
  EXPECT_NEAR(pid.status().rate_derivative.x(), alpha * 10.0, 1e-9);
  EXPECT_NEAR(pid.status().derivative.x(), -pid.params().d.x() * alpha * 10.0, 1e-9);
  EXPECT_EQ(pid.status().derivative.y(), 0.0);
}

TEST(RateController, IntegralIsBoundedByItsLimit) {
  RateController pid;
  for (int i = 0; i < 100000; ++i) pid.update(Vec3::Zero(), Vec3(5.0, -5.0, 5.0), kRateLoopDt, false);
  const Vec3 limit = pid.params().integral_limit;
  EXPECT_NEAR(pid.status().integral.x(), limit.x(), 1e-12);
  EXPECT_NEAR(pid.status().integral.y(), -limit.y(), 1e-12);
  EXPECT_NEAR(pid.status().integral.z(), limit.z(), 1e-12);
}

TEST(RateController, IntegralFreezesInTheSaturatedDirectionOnly) {
  RateController pid;
  AxisFlags positive = AxisFlags::Constant(false), negative = AxisFlags::Constant(false);
  positive[0] = true;  // the mixer cannot add more roll torque
  pid.setSaturation(positive, negative);
  for (int i = 0; i < 100; ++i) pid.update(Vec3::Zero(), Vec3(1.0, 1.0, 0.0), kRateLoopDt, false);
  EXPECT_EQ(pid.status().integral.x(), 0.0);       // frozen: would wind up
  EXPECT_GT(pid.status().integral.y(), 0.0);       // not saturated: integrates
  for (int i = 0; i < 100; ++i) pid.update(Vec3::Zero(), Vec3(-1.0, 0.0, 0.0), kRateLoopDt, false);
  EXPECT_LT(pid.status().integral.x(), 0.0);       // unwinding is always allowed
}

TEST(RateController, LandedResetsTheIntegral) {
  RateController pid;
  for (int i = 0; i < 500; ++i) pid.update(Vec3::Zero(), Vec3(1.0, 1.0, 1.0), kRateLoopDt, false);
  ASSERT_GT(pid.status().integral.norm(), 0.0);
  pid.update(Vec3::Zero(), Vec3(1.0, 1.0, 1.0), kRateLoopDt, true);
  EXPECT_EQ(pid.status().integral, Vec3::Zero());
  for (int i = 0; i < 500; ++i) pid.update(Vec3::Zero(), Vec3(1.0, 1.0, 1.0), kRateLoopDt, true);
  EXPECT_EQ(pid.status().integral, Vec3::Zero());
}

TEST(RateController, ProportionalTermFollowsTheGains) {
  RateControlParams params;
  params.p = Vec3(10.0, 20.0, 3.0);
  params.i.setZero();
  params.d.setZero();
  RateController pid(params);
  const Vec3 out = pid.update(Vec3(0.5, 0.0, -1.0), Vec3(1.0, 1.0, 1.0), kRateLoopDt, false);
  EXPECT_TRUE(out.isApprox(Vec3(5.0, 20.0, 6.0), 1e-12));
}

TEST(RateControlParams, InvalidValuesNameTheirKey) {
  RateControlParams params;
  EXPECT_TRUE(params.valid());
  params.p[1] = -1.0;
  EXPECT_EQ(params.invalidReason().rfind("p[1]:", 0), 0u);
  params = RateControlParams();
  params.d_cutoff_hz = 0.0;
  EXPECT_EQ(params.invalidReason().rfind("d_cutoff_hz:", 0), 0u);
}

}  // namespace
}  // namespace sdlqr::lowlevel
