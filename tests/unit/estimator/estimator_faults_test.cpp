// Behaviour of the estimator under bad inputs and outages: rejection and counting of bad
// messages without side effects, VIO dropout and recovery, re-initialisation, restarts.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

#include "estimator_run.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/estimator/estimator.hpp"

namespace sdlqr::estimator::test {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Feeds events with arrival time < until_utime; returns the index of the first one not fed.
size_t feedUntil(Estimator& estimator, const std::vector<SensorEvent>& events, size_t from, int64_t until_utime) {
  size_t i = from;
  for (; i < events.size() && events[i].arrival_utime < until_utime; ++i) {
    if (events[i].kind == SensorEvent::Kind::kImu) {
      estimator.onImu(events[i].imu);
    } else {
      estimator.onVio(events[i].vio);
    }
  }
  return i;
}

void expectSameState(const Estimator& a, const Estimator& b) {
  EXPECT_EQ(a.stateUtime(), b.stateUtime());
  EXPECT_EQ(a.state().position, b.state().position);
  EXPECT_EQ(a.state().velocity, b.state().velocity);
  EXPECT_EQ(a.state().orientation, b.state().orientation);
  EXPECT_EQ(a.state().gyro_bias, b.state().gyro_bias);
  EXPECT_EQ(a.state().accel_bias, b.state().accel_bias);
  EXPECT_EQ(a.covariance(), b.covariance());
}

class HoverFixture : public ::testing::Test {
 protected:
  HoverFixture()
      : sensors_(AnalyticTrajectory(TrajectorySpec::hover(Vec3(0.5, 0.5, 1.0), -0.4)), SensorSpec()),
        events_(sensors_.run(6.0)) {}

  // The newest pose fused so far in events_[0, end).
  const VioPose& lastPoseBefore(size_t end) const {
    size_t i = end;
    while (events_[--i].kind != SensorEvent::Kind::kVio) {
    }
    return events_[i].vio;
  }

  // The same events up to until_utime to a filter and its twin, which will not see the bad inputs
  // that follow: what the filter must still equal. Returns the index of the first event not fed.
  size_t feedBoth(Estimator& estimator, Estimator& twin, int64_t until_utime) const {
    feedUntil(twin, events_, 0, until_utime);
    return feedUntil(estimator, events_, 0, until_utime);
  }

  SensorSimulator sensors_;
  std::vector<SensorEvent> events_;
};

TEST_F(HoverFixture, RejectsOutOfOrderTooOldAndFuturePosesWithoutTouchingTheState) {
  // GIVEN a converged filter 3 s into a hover, and a twin that will not see the bad poses
  Estimator estimator{EstimatorParams()};
  Estimator twin{EstimatorParams()};
  const size_t now = feedBoth(estimator, twin, 3'000'000);
  const VioPose last = lastPoseBefore(now);
  const int64_t imu_now = estimator.stateUtime();

  // WHEN it receives a repeated pose, a pose older than the last fused one and a pose from the
  // future
  VioPose repeated = last;
  VioPose older = last;
  older.utime -= 10'000;
  VioPose future = last;
  future.utime = imu_now + 50'000;

  // THEN each is rejected for its own reason and counted, and the state is untouched
  EXPECT_EQ(estimator.onVio(repeated), VioOutcome::kRejected);
  EXPECT_EQ(estimator.lastVioRejection(), RejectReason::kTimeBackwards);
  EXPECT_EQ(estimator.onVio(older), VioOutcome::kRejected);
  EXPECT_EQ(estimator.lastVioRejection(), RejectReason::kTimeBackwards);
  EXPECT_EQ(estimator.onVio(future), VioOutcome::kRejected);
  EXPECT_EQ(estimator.lastVioRejection(), RejectReason::kTimeFuture);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kTimeBackwards), 2);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kTimeFuture), 1);
  expectSameState(estimator, twin);

  // (a pose newer than the last fused one but older than the history needs a VIO gap first)
  Estimator gapped{EstimatorParams()};
  size_t i = feedUntil(gapped, events_, 0, 2'000'000);
  for (; events_[i].arrival_utime < 2'500'000; ++i) {
    if (events_[i].kind == SensorEvent::Kind::kImu) gapped.onImu(events_[i].imu);
  }
  VioPose stale = events_[i - 1].kind == SensorEvent::Kind::kVio ? events_[i - 1].vio : lastPoseBefore(i);
  stale.utime = gapped.stateUtime() - 300'000;
  stale.seq = 10'000;
  EXPECT_EQ(gapped.onVio(stale), VioOutcome::kRejected);
  EXPECT_EQ(gapped.lastVioRejection(), RejectReason::kStale);
  EXPECT_EQ(gapped.counters().vioRejected(RejectReason::kStale), 1);
}

TEST_F(HoverFixture, RejectsMalformedPosesWithoutTouchingTheState) {
  // GIVEN a converged filter and a twin
  Estimator estimator{EstimatorParams()};
  Estimator twin{EstimatorParams()};
  const size_t now = feedBoth(estimator, twin, 3'000'000);
  VioPose good = lastPoseBefore(now);
  good.utime = estimator.stateUtime();  // newer than the last fused, inside the history

  // WHEN poses with NaN, a non-unit quaternion or a negative std arrive
  VioPose nan_position = good;
  nan_position.position.x() = kNan;
  VioPose nan_std = good;
  nan_std.attitude_std = kNan;
  VioPose long_quaternion = good;
  long_quaternion.orientation *= 1.2;
  VioPose negative_std = good;
  negative_std.position_std = -0.01;

  // THEN each is rejected for its reason and counted, and nothing changed
  EXPECT_EQ(estimator.onVio(nan_position), VioOutcome::kRejected);
  EXPECT_EQ(estimator.onVio(nan_std), VioOutcome::kRejected);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kNonFinite), 2);
  EXPECT_EQ(estimator.onVio(long_quaternion), VioOutcome::kRejected);
  EXPECT_EQ(estimator.lastVioRejection(), RejectReason::kQuaternionNorm);
  EXPECT_EQ(estimator.onVio(negative_std), VioOutcome::kRejected);
  EXPECT_EQ(estimator.lastVioRejection(), RejectReason::kOutOfRange);
  expectSameState(estimator, twin);
  // AND the good pose is still fused afterwards
  EXPECT_EQ(estimator.onVio(good), VioOutcome::kFused);
}

TEST_F(HoverFixture, GatesAPoseThatJumpsAway) {
  // GIVEN a converged filter
  Estimator estimator{EstimatorParams()};
  Estimator twin{EstimatorParams()};
  const size_t now = feedBoth(estimator, twin, 3'000'000);

  // WHEN a pose 0.5 m away from the others arrives
  VioPose jump = lastPoseBefore(now);
  jump.utime = estimator.stateUtime();
  jump.position.z() += 0.5;

  // THEN the chi-square gate rejects it and the state is unchanged
  EXPECT_EQ(estimator.onVio(jump), VioOutcome::kRejected);
  EXPECT_EQ(estimator.lastVioRejection(), RejectReason::kGated);
  expectSameState(estimator, twin);
}

TEST_F(HoverFixture, NanImuSampleIsRejectedAsIfItNeverArrived) {
  // GIVEN two filters on the same hover, one of which will see NaN samples in place of two IMU
  // samples the other simply never receives
  Estimator with_nan{EstimatorParams()};
  Estimator without{EstimatorParams()};
  const std::vector<int64_t> corrupted = {3'000'000, 3'101'000};  // one closes a window, one inside one

  // WHEN both run to the end
  for (const SensorEvent& e : events_) {
    if (e.kind == SensorEvent::Kind::kVio) {
      with_nan.onVio(e.vio);
      without.onVio(e.vio);
      continue;
    }
    if (e.imu.utime == corrupted[0] || e.imu.utime == corrupted[1]) {
      ImuSample bad = e.imu;
      (e.imu.utime == corrupted[0] ? bad.gyro.y() : bad.accel.z()) = kNan;
      EXPECT_FALSE(with_nan.onImu(bad).has_value());
      continue;
    }
    const auto a = with_nan.onImu(e.imu);
    const auto b = without.onImu(e.imu);
    ASSERT_EQ(a.has_value(), b.has_value());
    if (a) {
      ASSERT_TRUE(a->state().allFinite());
    }
  }

  // THEN the rejected samples were counted and left no trace: both states are bit-identical
  EXPECT_EQ(with_nan.counters().imuRejected(RejectReason::kNonFinite), 2);
  EXPECT_EQ(without.counters().rejectedTotal(), 0);
  expectSameState(with_nan, without);
  EXPECT_TRUE(with_nan.healthy());
}

TEST_F(HoverFixture, OutOfRangeAndBackwardImuSamplesAreRejected) {
  // GIVEN a running filter
  Estimator estimator{EstimatorParams()};
  Estimator twin{EstimatorParams()};
  const size_t now = feedBoth(estimator, twin, 2'000'000);
  ImuSample sample = events_[now].imu;

  // WHEN samples arrive with a 50 rad/s gyro, a 200 m/s^2 accel, an old and a duplicate timestamp
  ImuSample spinning = sample;
  spinning.gyro.x() = 50.0;
  ImuSample slamming = sample;
  slamming.accel.z() = -200.0;
  ImuSample old = sample;
  old.utime = estimator.stateUtime() - 1000;
  ImuSample duplicate = sample;
  duplicate.utime = estimator.stateUtime();  // the last sample was on the grid

  // THEN each is rejected and counted, nothing changes
  EXPECT_FALSE(estimator.onImu(spinning));
  EXPECT_FALSE(estimator.onImu(slamming));
  EXPECT_EQ(estimator.counters().imuRejected(RejectReason::kOutOfRange), 2);
  EXPECT_FALSE(estimator.onImu(old));
  EXPECT_FALSE(estimator.onImu(duplicate));
  EXPECT_EQ(estimator.counters().imuRejected(RejectReason::kTimeBackwards), 2);
  expectSameState(estimator, twin);
}

TEST(EstimatorDropout, VioTimeoutAfterTheConfiguredTimeAndRecovery) {
  // GIVEN agile flight whose poses captured between 8 s and 9 s are lost (1 s > vio_timeout)
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  const auto events = sensors.run(14.0);
  const EstimatorParams params;
  Estimator estimator{params};
  int64_t last_before_gap = 0;

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events, [&](VioPose& pose) {
    if (pose.utime < 8'000'000) last_before_gap = std::max(last_before_gap, pose.utime);
    return pose.utime < 8'000'000 || pose.utime >= 9'000'000;
  });

  // THEN the status turns VIO_TIMEOUT exactly when the newest fused capture is older than
  // vio_timeout, and back to OK with the first pose after the gap, without re-initialising
  int64_t timeout_start = -1, timeout_end = -1;
  for (const OutputRecord& r : run.outputs) {
    if (r.estimate.status == EstimatorStatus::kVioTimeout && timeout_start < 0) timeout_start = r.estimate.utime;
    if (r.estimate.status == EstimatorStatus::kVioTimeout) timeout_end = r.estimate.utime;
  }
  ASSERT_GT(timeout_start, 0);
  const double timeout_after = seconds(timeout_start - last_before_gap);
  std::cout << "[ measured ] VIO_TIMEOUT " << timeout_after * 1e3 << " ms after the last fused capture, for "
            << seconds(timeout_end - timeout_start) << " s; worst position error in the gap "
            << run.maxPositionError(8.0, 9.2) * 1e3 << " mm\n";
  EXPECT_GT(timeout_after, params.vio_timeout);
  EXPECT_LE(timeout_after, params.vio_timeout + 0.004);
  EXPECT_LT(seconds(timeout_end), 9.1);  // first pose after the gap arrives by 9.05 s
  EXPECT_EQ(run.outputs.back().estimate.status, EstimatorStatus::kOk);
  EXPECT_EQ(estimator.counters().initializations, 1);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), 0);
  // AND accuracy is back within targets a second after the gap
  EXPECT_LT(run.positionRms(10.0, 14.0), 0.03);
  EXPECT_LT(run.attitudeRmsDeg(10.0, 14.0), 1.0);
}

TEST(EstimatorDropout, ReinitialisesFromTheNextPoseAfterALongGap) {
  // GIVEN hover whose poses are lost for 3 s (> reinit_after), after which the VIO has
  // relocalised with its world frame shifted by 0.4 m (so a plain update would be gated)
  const Vec3 shift(0.4, 0.0, 0.0);
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec::hover(Vec3(0.0, 0.0, 1.0), 0.0)), SensorSpec()};
  const auto events = sensors.run(8.0);
  Estimator estimator{EstimatorParams()};

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events, [&](VioPose& pose) {
    if (pose.utime >= 5'000'000) pose.position += shift;
    return pose.utime < 2'000'000 || pose.utime >= 5'000'000;
  });

  // THEN the first pose after the gap re-initialises the filter and it follows the new frame
  EXPECT_EQ(estimator.counters().initializations, 2);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), 0);
  const StateEstimate& final_estimate = run.outputs.back().estimate;
  const Vec3 truth = sensors.truthAt(final_estimate.utime).position + shift;
  std::cout << "[ measured ] after re-initialisation: position error " << (final_estimate.position - truth).norm() * 1e3
            << " mm in the shifted frame\n";
  EXPECT_EQ(final_estimate.status, EstimatorStatus::kOk);
  EXPECT_LT((final_estimate.position - truth).norm(), 0.03);
}

TEST(EstimatorRestart, AnEstimatorStartedMidFlightInitialisesAndConverges) {
  // GIVEN the agile flight, joined 10 s in by a freshly started estimator (velocity up to 3 m/s)
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  const auto all = sensors.run(16.0);
  std::vector<SensorEvent> events;
  for (const SensorEvent& e : all) {
    if (e.arrival_utime >= 10'000'000) events.push_back(e);
  }
  Estimator estimator{EstimatorParams()};

  // WHEN it runs from there
  const RunResult run = runEstimator(estimator, sensors, events);

  // THEN it initialises from the first pose (zero velocity), no later pose is gated, and after a
  // second it meets the targets
  EXPECT_EQ(estimator.counters().initializations, 1);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), 0);
  const double pos_rms = run.positionRms(11.0, 16.0), att_rms = run.attitudeRmsDeg(11.0, 16.0);
  std::cout << "[ measured ] restarted mid-flight: position RMS " << pos_rms * 1e3 << " mm, attitude RMS " << att_rms
            << " deg (from 1 s after start)\n";
  EXPECT_LT(pos_rms, 0.03);
  EXPECT_LT(att_rms, 1.0);
}

TEST(EstimatorRestart, RestartsOnANewImuClock) {
  // GIVEN a filter running for 3 s, after which the simulator restarts: IMU time begins at 0 again
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec::hover(Vec3(0.0, 0.0, 1.0), 0.0)), SensorSpec()};
  const auto events = sensors.run(3.0);
  const EstimatorParams params;
  Estimator estimator{params};
  feedUntil(estimator, events, 0, 3'000'000);
  ASSERT_TRUE(estimator.healthy());

  // WHEN the restarted stream arrives
  const RunResult run = runEstimator(estimator, sensors, events);

  // THEN after imu_time_reset_count samples in a row behind the old clock the filter starts over
  // on the new clock, re-initialises from the next pose and is healthy again
  EXPECT_EQ(estimator.counters().clock_resets, 1);
  EXPECT_EQ(estimator.counters().imuRejected(RejectReason::kTimeBackwards), params.imu_time_reset_count);
  EXPECT_EQ(estimator.counters().initializations, 2);
  EXPECT_TRUE(estimator.healthy());
  EXPECT_LT(run.positionRms(1.0, 3.0), 0.03);
}

}  // namespace
}  // namespace sdlqr::estimator::test
