// Recovery from a filter that has gone wrong: when VIO poses keep failing the gate while agreeing
// with one another for vio_reset_after, the filter resets to them (position, attitude, and the
// velocity error their drift reveals) instead of dead-reckoning until re-initialisation. Outliers
// that do not agree with one another never cause a reset.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "estimator_run.hpp"
#include "landing_trajectory.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/estimator/estimator.hpp"

namespace sdlqr::estimator::test {
namespace {

// Capture time of every pose handed over, in the order of RunResult::vio_outcomes.
struct PoseLog {
  std::vector<int64_t> captures;

  // Index of the first pose with the outcome at or after from_utime; -1 if none.
  int first(const RunResult& run, VioOutcome outcome, int64_t from_utime = 0) const {
    for (size_t i = 0; i < captures.size(); ++i) {
      if (captures[i] >= from_utime && run.vio_outcomes[i] == outcome) return static_cast<int>(i);
    }
    return -1;
  }
  int count(const RunResult& run, VioOutcome outcome, int64_t from_utime, int64_t to_utime) const {
    int n = 0;
    for (size_t i = 0; i < captures.size(); ++i) {
      n += captures[i] >= from_utime && captures[i] < to_utime && run.vio_outcomes[i] == outcome;
    }
    return n;
  }
};

// RMS over outputs in [from, to) seconds of the position error against truth + shift.
double shiftedPositionRms(const RunResult& run, const SensorSimulator& sensors, const Vec3& shift, double from,
                          double to) {
  double sum = 0.0;
  int n = 0;
  for (const OutputRecord& r : run.outputs) {
    const double t = seconds(r.estimate.utime);
    if (t < from || t >= to) continue;
    sum += (r.estimate.position - sensors.truthAt(r.estimate.utime).position - shift).squaredNorm();
    ++n;
  }
  return std::sqrt(sum / std::max(n, 1));
}

TEST(EstimatorVioReset, APersistentVioFrameJumpResetsTheFilterWithinTheConfiguredTime) {
  // GIVEN agile flight (figure-eights up to 3 m/s) whose VIO world frame jumps 0.3 m at 8 s, as
  // after a relocalisation, and stays there
  const Vec3 shift(0.3, 0.0, 0.0);
  const int64_t jump = 8'000'000;
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  const auto events = sensors.run(12.0);
  const EstimatorParams params;
  Estimator estimator{params};
  PoseLog poses;

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events, [&](VioPose& pose) {
    if (pose.utime >= jump) pose.position += shift;
    poses.captures.push_back(pose.utime);
    return true;
  });

  // THEN the jumped poses are gated until they have agreed for vio_reset_after, then the filter
  // resets to the pose completing that run: one reset, no re-initialisation, never VIO_TIMEOUT
  const int first_jumped = static_cast<int>(
      std::find_if(poses.captures.begin(), poses.captures.end(), [&](int64_t t) { return t >= jump; }) -
      poses.captures.begin());
  const int reset = poses.first(run, VioOutcome::kReset);
  ASSERT_GE(reset, 0);
  const double reset_after_jump = seconds(poses.captures[reset] - poses.captures[first_jumped]);
  const int gated_before_reset = poses.count(run, VioOutcome::kRejected, jump, poses.captures[reset]);
  const double rms_after = shiftedPositionRms(run, sensors, shift, 9.0, 12.0);
  const auto after_reset = std::find_if(run.outputs.begin(), run.outputs.end(), [&](const OutputRecord& r) {
    return r.estimate.utime > poses.captures[reset] + 50'000;  // published after the reset pose arrived
  });
  ASSERT_NE(after_reset, run.outputs.end());
  const StateEstimate& at_reset = after_reset->estimate;
  const double velocity_error_at_reset = (at_reset.velocity - sensors.truthAt(at_reset.utime).velocity).norm();
  std::cout << "[ measured ] reset " << reset_after_jump * 1e3 << " ms of capture time after the jump, " << gated_before_reset
            << " poses gated before; velocity error after the reset " << velocity_error_at_reset
            << " m/s; position RMS in the new frame from 1 s after the jump " << rms_after * 1e3 << " mm\n";
  EXPECT_EQ(estimator.counters().vio_resets, 1);
  EXPECT_EQ(estimator.counters().initializations, 1);
  EXPECT_GE(reset_after_jump, params.vio_reset_after);
  EXPECT_LE(reset_after_jump, params.vio_reset_after + 1.0 / 30.0 + 0.002);  // the next frame after it
  EXPECT_EQ(gated_before_reset, reset - first_jumped);  // every jumped pose until then
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), gated_before_reset);
  EXPECT_EQ(run.countStatus(EstimatorStatus::kVioTimeout), 0);
  // AND the filter follows the new frame with the usual accuracy, its velocity undisturbed: a
  // frame jump carries no velocity error, and the run's drift (noise, ~0.035 m/s per axis) is
  // not applied (flight velocity RMS is ~0.01 m/s)
  EXPECT_LT(velocity_error_at_reset, 0.03);
  EXPECT_LT(rms_after, 0.03);
  EXPECT_EQ(poses.count(run, VioOutcome::kRejected, poses.captures[reset], 12'000'000), 0);
}

TEST(EstimatorVioReset, ASingleOutlierIsStillGatedAndCausesNoReset) {
  // GIVEN agile flight with one pose 0.5 m off at 8 s
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  const auto events = sensors.run(12.0);
  Estimator estimator{EstimatorParams()};
  Estimator clean{EstimatorParams()};
  bool corrupted = false;

  // WHEN the estimator runs on it (and a twin without the outlier)
  const RunResult run = runEstimator(estimator, sensors, events, [&](VioPose& pose) {
    if (!corrupted && pose.utime >= 8'000'000) {
      pose.position.z() += 0.5;
      corrupted = true;
    }
    return true;
  });
  const RunResult reference = runEstimator(clean, sensors, events);

  // THEN that pose is gated, the next is fused again, and nothing else changes
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), 1);
  EXPECT_EQ(estimator.counters().vio_resets, 0);
  EXPECT_EQ(estimator.counters().vio_fused, clean.counters().vio_fused - 1);
  EXPECT_LT(run.positionRms(8.0, 12.0), 1.1 * reference.positionRms(8.0, 12.0));
}

TEST(EstimatorVioReset, OutliersThatDisagreeWithOneAnotherNeverReset) {
  // GIVEN agile flight where for 0.8 s every pose is 0.5 m off, in a direction that turns by 90
  // degrees from one pose to the next (a VIO producing garbage, not a shifted frame)
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  const auto events = sensors.run(12.0);
  Estimator estimator{EstimatorParams()};
  PoseLog poses;
  int garbage = 0;

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events, [&](VioPose& pose) {
    if (pose.utime >= 8'000'000 && pose.utime < 8'800'000) {
      const double angle = 0.5 * M_PI * garbage++;
      pose.position += 0.5 * Vec3(std::cos(angle), std::sin(angle), 0.0);
    }
    poses.captures.push_back(pose.utime);
    return true;
  });

  // THEN every garbage pose is gated, none causes a reset, and the good poses afterwards are
  // fused again (the gap is shorter than reinit_after) with the usual accuracy regained
  std::cout << "[ measured ] " << garbage << " garbage poses, " << estimator.counters().vioRejected(RejectReason::kGated)
            << " gated; position RMS from 1.2 s after the burst " << run.positionRms(10.0, 12.0) * 1e3 << " mm\n";
  EXPECT_GE(garbage, 20);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), garbage);
  EXPECT_EQ(estimator.counters().vio_resets, 0);
  EXPECT_EQ(estimator.counters().initializations, 1);
  EXPECT_EQ(poses.count(run, VioOutcome::kRejected, 8'800'000, 12'000'000), 0);
  EXPECT_LT(run.positionRms(10.0, 12.0), 0.03);
}

TEST(EstimatorVioReset, AFilterWhoseVelocityWentWrongIsResetWithTheVelocityCorrected) {
  // GIVEN a touchdown whose clipped accelerometer sample the estimator cannot see as clipped
  // (clip level above the sensor's range): it loses 0.25 m/s and believes it keeps sinking
  LandingSpec spec;
  SensorSimulator sensors{LandingTrajectory(spec), SensorSpec()};
  const auto events = sensors.run(spec.touchdown_time + 2.0);
  EstimatorParams params;
  params.accel_clip_level = params.accel_range;
  Estimator estimator{params};
  PoseLog poses;

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events, [&](VioPose& pose) {
    poses.captures.push_back(pose.utime);
    return true;
  });

  // THEN the resting vehicle's poses are gated (a noisy one may still pass while the drift is
  // small, which starts the run anew), and once they have agreed for vio_reset_after in a row the
  // filter resets, with the velocity error found from their drift, not left to re-initialisation
  const auto touchdown = static_cast<int64_t>(std::llround(spec.touchdown_time * 1e6));
  const int reset = poses.first(run, VioOutcome::kReset, touchdown);
  ASSERT_GE(reset, 0);
  int run_start = reset;
  while (run.vio_outcomes[static_cast<size_t>(run_start - 1)] == VioOutcome::kRejected) --run_start;
  ASSERT_GT(poses.captures[static_cast<size_t>(run_start)], touchdown);
  const auto after_reset = std::find_if(run.outputs.begin(), run.outputs.end(), [&](const OutputRecord& r) {
    return r.estimate.utime > poses.captures[reset] + 50'000;  // published after the reset pose arrived
  });
  ASSERT_NE(after_reset, run.outputs.end());
  double worst_velocity_later = 0.0;
  for (auto r = after_reset; r != run.outputs.end(); ++r) worst_velocity_later = std::max(worst_velocity_later, r->velocity_error);
  const double run_length = seconds(poses.captures[reset] - poses.captures[run_start]);
  const int first_gated = poses.first(run, VioOutcome::kRejected, touchdown);
  std::cout << "[ measured ] first pose gated " << seconds(poses.captures[first_gated] - touchdown) * 1e3
            << " ms after touchdown; reset " << run_length * 1e3 << " ms after the run began, "
            << seconds(poses.captures[reset] - touchdown) * 1e3 << " ms after touchdown; vertical velocity just after it " << after_reset->estimate.velocity.z()
            << " m/s (was " << run.outputs[static_cast<size_t>(after_reset - run.outputs.begin()) - 20].estimate.velocity.z()
            << "), worst velocity error from then on " << worst_velocity_later << " m/s\n";
  EXPECT_EQ(estimator.counters().vio_resets, 1);
  EXPECT_EQ(estimator.counters().initializations, 1);
  EXPECT_GE(run_length, params.vio_reset_after);
  EXPECT_LE(run_length, params.vio_reset_after + 1.0 / 30.0 + 0.002);
  EXPECT_LT(seconds(poses.captures[reset] - touchdown), 0.5 * params.reinit_after);
  // the regression over ~10 poses with 1 cm noise has a std of ~0.035 m/s
  EXPECT_LT(std::abs(after_reset->estimate.velocity.z()), 0.1);
  EXPECT_LT(after_reset->position_error, 0.03);
  EXPECT_LT(worst_velocity_later, 0.15);
}

}  // namespace
}  // namespace sdlqr::estimator::test
