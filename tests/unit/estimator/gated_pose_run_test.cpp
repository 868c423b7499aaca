#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/estimator/gated_pose_run.hpp"

namespace sdlqr::estimator {
namespace {

constexpr double kGate = 28.0;
constexpr int64_t kResetAfterUs = 300'000;
constexpr int64_t kFrameUs = 33'334;  // VIO at 30 Hz on the 1 ms simulator grid: 33 or 34 ms

// A gated pose's innovation: position part as given, attitude zero, covariance 1 cm / 8 mrad.
PoseUpdateResult gatedPose(const Vec3& position_innovation) {
  PoseUpdateResult r;
  r.innovation.head<3>() = position_innovation;
  r.innovation_cov.diagonal() << Vec3::Constant(1e-4), Vec3::Constant(6.4e-5);
  return r;
}

TEST(GatedPoseRun, AgreeingPosesSpanningResetAfterCallForAReset) {
  // GIVEN poses 0.3 m off, as after a VIO frame jump
  GatedPoseRun run(kGate, kResetAfterUs);
  // WHEN one arrives every 33 ms
  int k = 0;
  for (; k < 9; ++k) EXPECT_FALSE(run.add(1'000'000 + k * kFrameUs, gatedPose(Vec3(0.3, 0.0, 0.0)))) << k;
  // THEN the tenth, 300 ms after the first, completes the run (and not a microsecond earlier)
  GatedPoseRun early = run;
  EXPECT_FALSE(early.add(1'000'000 + kResetAfterUs - 1, gatedPose(Vec3(0.3, 0.0, 0.0))));
  EXPECT_TRUE(run.add(1'000'000 + k * kFrameUs, gatedPose(Vec3(0.3, 0.0, 0.0))));
  EXPECT_EQ(run.size(), 10);
  EXPECT_EQ(run.firstUtime(), 1'000'000);
  // and a constant offset means no velocity error
  EXPECT_LT(run.positionDriftRate().norm(), 1e-12);
}

TEST(GatedPoseRun, TheSlopeOfTheInnovationIsTheVelocityError) {
  // GIVEN a filter sinking at 0.25 m/s while the vehicle rests: the innovation grows linearly
  GatedPoseRun run(kGate, kResetAfterUs);
  for (int k = 0; k < 6; ++k) run.add(k * kFrameUs, gatedPose(Vec3(0.0, 0.0, 0.05 + 0.25 * k * kFrameUs * 1e-6)));
  // THEN the least-squares slope recovers it, with the variance of a regression on 6 points
  EXPECT_NEAR(run.positionDriftRate().z(), 0.25, 1e-9);
  EXPECT_NEAR(run.positionDriftRate().x(), 0.0, 1e-12);
  double spread = 0.0;  // sum of (t - mean)^2 for t = k * frame, k = 0..5
  for (int k = 0; k < 6; ++k) spread += std::pow((k - 2.5) * kFrameUs * 1e-6, 2);
  EXPECT_NEAR(run.positionDriftRateVariance(1e-4), 1e-4 / spread, 1e-9);
}

TEST(GatedPoseRun, APoseThatDisagreesStartsANewRun) {
  // GIVEN a run of agreeing poses
  GatedPoseRun run(kGate, kResetAfterUs);
  for (int k = 0; k < 8; ++k) run.add(k * kFrameUs, gatedPose(Vec3(0.3, 0.0, 0.0)));
  ASSERT_EQ(run.size(), 8);
  // WHEN an outlier elsewhere arrives (0.3 m apart: far beyond the VIO noise)
  EXPECT_FALSE(run.add(8 * kFrameUs, gatedPose(Vec3(0.0, 0.3, 0.0))));
  // THEN the run starts over from it, so the next agreeing pose does not complete 300 ms
  EXPECT_EQ(run.size(), 1);
  EXPECT_EQ(run.firstUtime(), 8 * kFrameUs);
  EXPECT_FALSE(run.add(9 * kFrameUs, gatedPose(Vec3(0.3, 0.0, 0.0))));
  EXPECT_EQ(run.size(), 1);
  // AND an innovation changing by the VIO noise only (2 cm against sqrt(2) cm) still agrees
  EXPECT_FALSE(run.add(10 * kFrameUs, gatedPose(Vec3(0.31, -0.01, 0.01))));
  EXPECT_EQ(run.size(), 2);
  // AND after clear() everything starts afresh
  run.clear();
  EXPECT_EQ(run.size(), 0);
  EXPECT_EQ(run.positionDriftRate(), Vec3::Zero());
}

}  // namespace
}  // namespace sdlqr::estimator
