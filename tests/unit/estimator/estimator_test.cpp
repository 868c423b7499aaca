// Behaviour of the estimator on simulated flights: initialisation, accuracy in hover and in
// agile flight, the value of fusing at capture time, output timing.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include <Eigen/Cholesky>

#include "estimator_run.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/estimator/estimator.hpp"

namespace sdlqr::estimator::test {
namespace {

constexpr double kPositionTarget = 0.03;  // [m] RMS, integration target
constexpr double kAttitudeTargetDeg = 1.0;

TEST(Estimator, InitialisesFromTheFirstVioPose) {
  // GIVEN a hovering vehicle whose IMU has been running for 0.5 s without any pose
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec::hover(Vec3(1.0, -2.0, 1.5), 0.7)), SensorSpec()};
  const std::vector<SensorEvent> events = sensors.run(1.0);
  Estimator estimator{EstimatorParams()};
  std::optional<StateEstimate> last;
  size_t i = 0;
  for (; i < events.size() && events[i].arrival_utime < 500'000; ++i) {
    if (events[i].kind == SensorEvent::Kind::kImu) {
      if (auto out = estimator.onImu(events[i].imu)) last = out;
    }
  }
  ASSERT_TRUE(last.has_value());
  EXPECT_EQ(last->status, EstimatorStatus::kInitializing);
  EXPECT_EQ(last->vio_seq, -1);
  EXPECT_FALSE(estimator.healthy());

  // WHEN the next pose arrives (30-50 ms after its capture)
  for (; events[i].kind != SensorEvent::Kind::kVio; ++i) estimator.onImu(events[i].imu);
  const VioPose& pose = events[i].vio;
  EXPECT_EQ(estimator.onVio(pose), VioOutcome::kInitialized);
  std::optional<StateEstimate> first;
  for (++i; !first; ++i) {
    if (events[i].kind == SensorEvent::Kind::kImu) first = estimator.onImu(events[i].imu);
  }

  // THEN the filter starts from that pose: position and attitude of the pose (carried forward by
  // the IMU over the latency, which in hover moves them by well under a millimetre / milliradian),
  // velocity zero, status OK
  EXPECT_EQ(first->status, EstimatorStatus::kOk);
  EXPECT_TRUE(estimator.healthy());
  EXPECT_EQ(first->vio_seq, pose.seq);
  EXPECT_LT((first->position - pose.position).norm(), 1e-3);
  EXPECT_LT(quat::boxMinus(first->orientation, pose.orientation).norm(), 2e-3);
  EXPECT_LT(first->velocity.norm(), 0.05);
  // the position std is the pose's, grown by the initial velocity uncertainty over the latency
  const double since_capture = seconds(first->utime - pose.utime);
  const double sigma_v = EstimatorParams().initial_velocity_std;
  EXPECT_NEAR(first->position_std[0], std::hypot(pose.position_std, sigma_v * since_capture), 1e-3);
  EXPECT_NEAR(first->attitude_std[0], pose.attitude_std, 1e-3);
  std::cout << "[ measured ] latency " << seconds(pose.publish_utime - pose.utime) * 1e3 << " ms, init position offset "
            << (first->position - pose.position).norm() * 1e3 << " mm\n";
}

TEST(Estimator, StaticHoverMeetsTargetsAndBiasesConverge) {
  // GIVEN 40 s of hover with large constant-ish biases (near the simulator's drawing range)
  SensorSpec spec;
  spec.random_initial_bias = false;
  spec.initial_gyro_bias = Vec3(0.015, -0.012, 0.018);
  spec.initial_accel_bias = Vec3(0.08, -0.07, 0.09);
  spec.seed = 7;
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec::hover(Vec3(0.0, 0.0, 1.0), 0.3)), spec};
  const auto events = sensors.run(40.0);
  Estimator estimator{EstimatorParams()};

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events);

  // THEN errors after a 2 s settling time meet the targets
  const double pos_rms = run.positionRms(2.0, 40.0);
  const double att_rms = run.attitudeRmsDeg(2.0, 40.0);
  std::cout << "[ measured ] hover: position RMS " << pos_rms * 1e3 << " mm, attitude RMS " << att_rms << " deg\n";
  RecordProperty("hover_position_rms_mm", std::to_string(pos_rms * 1e3));
  RecordProperty("hover_attitude_rms_deg", std::to_string(att_rms));
  EXPECT_LT(pos_rms, kPositionTarget);
  EXPECT_LT(att_rms, kAttitudeTargetDeg);

  // AND the bias estimates have moved toward the true biases, within 3 sigma of the filter's own
  // uncertainty and to a small fraction of the initial error
  const StateEstimate& final_estimate = run.outputs.back().estimate;
  const Vec3 gyro_error = final_estimate.gyro_bias - sensors.gyroBiasAt(final_estimate.utime);
  const Vec3 accel_error = final_estimate.accel_bias - sensors.accelBiasAt(final_estimate.utime);
  const ErrorCovariance& p = estimator.covariance();
  std::cout << "[ measured ] gyro bias error " << gyro_error.transpose() << " (initial "
            << sensors.gyroBiasAt(0).transpose() << "), sigma "
            << p.diagonal().segment<3>(kErrGyroBias).cwiseSqrt().transpose() << "\n"
            << "[ measured ] accel bias error " << accel_error.transpose() << " (initial "
            << sensors.accelBiasAt(0).transpose() << "), sigma "
            << p.diagonal().segment<3>(kErrAccelBias).cwiseSqrt().transpose() << "\n";
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_LT(std::abs(gyro_error[axis]), 3.0 * std::sqrt(p(kErrGyroBias + axis, kErrGyroBias + axis))) << axis;
    EXPECT_LT(std::abs(accel_error[axis]), 3.0 * std::sqrt(p(kErrAccelBias + axis, kErrAccelBias + axis))) << axis;
  }
  EXPECT_LT(gyro_error.norm(), 0.1 * sensors.gyroBiasAt(0).norm());
  EXPECT_LT(accel_error.norm(), 0.25 * sensors.accelBiasAt(0).norm());
}

TEST(Estimator, AgileFigureEightMeetsTargets) {
  // GIVEN 2 s of hover, then figure-eights up to ~3 m/s, ~35 deg tilt and ~2.4 rad/s body rate
  SensorSpec spec;
  spec.seed = 11;
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), spec};
  const auto events = sensors.run(30.0);
  double max_tilt = 0.0, max_rate = 0.0, max_speed = 0.0;
  for (double t = 0.0; t < 30.0; t += 0.01) {
    const TruthSample truth = sensors.truthAt(static_cast<int64_t>(t * 1e6));
    max_tilt = std::max(max_tilt, quat::tilt(truth.orientation));
    max_rate = std::max(max_rate, truth.body_rate.norm());
    max_speed = std::max(max_speed, truth.velocity.norm());
  }
  Estimator estimator{EstimatorParams()};

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events);

  // THEN it stays healthy, fuses every pose and meets the targets over the agile part
  const double pos_rms = run.positionRms(4.0, 30.0);
  const double att_rms = run.attitudeRmsDeg(4.0, 30.0);
  const double vel_rms = run.velocityRms(4.0, 30.0);
  std::cout << "[ measured ] figure-eight (max tilt " << max_tilt * 180.0 / M_PI << " deg, max rate " << max_rate
            << " rad/s, max speed " << max_speed << " m/s): position RMS " << pos_rms * 1e3 << " mm, attitude RMS "
            << att_rms << " deg, velocity RMS " << vel_rms << " m/s\n";
  RecordProperty("agile_position_rms_mm", std::to_string(pos_rms * 1e3));
  RecordProperty("agile_attitude_rms_deg", std::to_string(att_rms));
  EXPECT_GT(max_tilt, 30.0 * M_PI / 180.0);  // the scenario really is agile
  EXPECT_GT(max_rate, 1.5);
  EXPECT_LT(pos_rms, kPositionTarget);
  EXPECT_LT(att_rms, kAttitudeTargetDeg);
  EXPECT_EQ(estimator.counters().vioRejected(RejectReason::kGated), 0);
  EXPECT_EQ(estimator.counters().rejectedTotal(), 0);
  EXPECT_EQ(run.countStatus(EstimatorStatus::kVioTimeout), 0);
}

TEST(Estimator, CovarianceMatchesTheActualErrors) {
  // GIVEN forty agile flights with different noise and bias draws
  double nees_sum[5] = {0, 0, 0, 0, 0};
  double nees_total = 0.0;
  int samples = 0;
  for (uint64_t seed = 21; seed <= 60; ++seed) {
    SensorSpec spec;
    spec.seed = seed;
    SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), spec};
    const auto events = sensors.run(20.0);
    Estimator estimator{EstimatorParams()};

    // WHEN the estimator runs, and its 15-dim error against the truth is weighed by its own
    // covariance every 0.1 s after 5 s (normalised estimation error squared, NEES)
    for (const SensorEvent& e : events) {
      if (e.kind == SensorEvent::Kind::kVio) {
        estimator.onVio(e.vio);
        continue;
      }
      const auto out = estimator.onImu(e.imu);
      if (!out || out->utime < 5'000'000 || out->utime % 100'000 != 0) continue;
      const TruthSample truth = sensors.truthAt(out->utime);
      const NavState& x = estimator.state();
      ErrorVector error;
      error.segment<3>(kErrPos) = truth.position - x.position;
      error.segment<3>(kErrVel) = truth.velocity - x.velocity;
      error.segment<3>(kErrRot) = quat::boxMinus(truth.orientation, x.orientation);
      error.segment<3>(kErrGyroBias) = sensors.gyroBiasAt(out->utime) - x.gyro_bias;
      error.segment<3>(kErrAccelBias) = sensors.accelBiasAt(out->utime) - x.accel_bias;
      const ErrorCovariance& p = estimator.covariance();
      nees_total += error.dot(p.ldlt().solve(error));
      for (int block = 0; block < 5; ++block) {
        const Vec3 e3 = error.segment<3>(3 * block);
        nees_sum[block] += e3.dot(p.block<3, 3>(3 * block, 3 * block).ldlt().solve(e3));
      }
      ++samples;
    }
  }

  // THEN the mean NEES is near the dimension (15 overall, 3 per block). Bias errors stay
  // correlated over a whole flight, so each flight counts about once: the per-flight mean of the
  // gyro-bias NEES scatters with a std of ~1.7 (measured over 240 flights), i.e. +-0.3 for the
  // mean of 40 flights (six flights gave 4.5 by chance); over batches of 40 flights it ranged
  // 2.7-3.4, the accelerometer bias's 2.7-3.2. Position, velocity and attitude decorrelate within
  // a few VIO frames; their batch means stayed within 2.8-3.2.
  const double band[5][2] = {{2.5, 3.5}, {2.5, 3.5}, {2.5, 3.5}, {2.0, 4.2}, {2.0, 4.2}};
  const char* names[5] = {"position", "velocity", "attitude", "gyro bias", "accel bias"};
  std::cout << "[ measured ] mean NEES over " << samples << " samples: all " << nees_total / samples;
  for (int block = 0; block < 5; ++block) std::cout << ", " << names[block] << " " << nees_sum[block] / samples;
  std::cout << "\n";
  EXPECT_GT(nees_total / samples, 12.5);
  EXPECT_LT(nees_total / samples, 17.5);
  for (int block = 0; block < 5; ++block) {
    EXPECT_GT(nees_sum[block] / samples, band[block][0]) << names[block];
    EXPECT_LT(nees_sum[block] / samples, band[block][1]) << names[block];
  }
}

TEST(Estimator, FusingAtCaptureTimeBeatsFusingAtArrival) {
  // GIVEN the same agile flight and the same poses for two estimators
  SensorSpec spec;
  spec.seed = 12;
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), spec};
  const auto events = sensors.run(20.0);
  Estimator at_capture{EstimatorParams()};
  Estimator at_arrival{EstimatorParams()};

  // WHEN one fuses each pose at its capture time and the other as if it had been captured when it
  // arrived (what a filter without a history buffer does)
  const RunResult capture = runEstimator(at_capture, sensors, events);
  const RunResult arrival = runEstimator(at_arrival, sensors, events, [](VioPose& pose) {
    pose.utime = pose.publish_utime;
    return true;
  });

  // THEN the capture-time filter is much more accurate
  const double capture_pos = capture.positionRms(4.0, 20.0), arrival_pos = arrival.positionRms(4.0, 20.0);
  const double capture_att = capture.attitudeRmsDeg(4.0, 20.0), arrival_att = arrival.attitudeRmsDeg(4.0, 20.0);
  std::cout << "[ measured ] at capture: position RMS " << capture_pos * 1e3 << " mm, attitude RMS " << capture_att
            << " deg; at arrival: position RMS " << arrival_pos * 1e3 << " mm, attitude RMS " << arrival_att
            << " deg, gated " << at_arrival.counters().vioRejected(RejectReason::kGated) << " of "
            << arrival.vio_outcomes.size() << "\n";
  RecordProperty("capture_vs_arrival_position_rms_mm",
                 std::to_string(capture_pos * 1e3) + " vs " + std::to_string(arrival_pos * 1e3));
  EXPECT_LT(2.0 * capture_pos, arrival_pos);
  EXPECT_LT(2.0 * capture_att, arrival_att);
}

TEST(Estimator, PublishesExactlyAtTheOutputRateInImuTime) {
  // GIVEN 10 s of 1 kHz IMU whose timestamps are jittered off the millisecond grid
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  auto events = sensors.run(10.0);
  int64_t k = 0;
  for (SensorEvent& e : events) {
    if (e.kind != SensorEvent::Kind::kImu) continue;
    e.imu.utime += 1137 + (k++ * 7919) % 300 - 150;  // deterministic +-150 us jitter, 1137 us offset
    e.arrival_utime = e.imu.utime;
  }
  Estimator estimator{EstimatorParams()};

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events);

  // THEN outputs come every 4000 us exactly, on multiples of 4000 us, with consecutive seq, one
  // per 4 ms of IMU time
  ASSERT_GT(run.outputs.size(), 2u);
  const int64_t period = EstimatorParams().outputPeriodUs();
  EXPECT_EQ(period, 4000);
  for (size_t i = 0; i < run.outputs.size(); ++i) {
    const StateEstimate& e = run.outputs[i].estimate;
    EXPECT_EQ(e.utime % period, 0) << i;
    EXPECT_EQ(e.seq, static_cast<int64_t>(i));
    if (i > 0) {
      EXPECT_EQ(e.utime - run.outputs[i - 1].estimate.utime, period) << i;
    }
  }
  const int64_t first_imu = events.front().imu.utime;
  int64_t last_imu = 0;
  for (const SensorEvent& e : events) {
    if (e.kind == SensorEvent::Kind::kImu) last_imu = e.imu.utime;
  }
  EXPECT_EQ(static_cast<int64_t>(run.outputs.size()), last_imu / period - first_imu / period);
  std::cout << "[ measured ] " << run.outputs.size() << " outputs over " << seconds(last_imu - first_imu)
            << " s of IMU time\n";
  // AND the jitter costs no accuracy
  EXPECT_LT(run.positionRms(4.0, 10.0), kPositionTarget);
  EXPECT_LT(run.attitudeRmsDeg(4.0, 10.0), kAttitudeTargetDeg);
}

TEST(Estimator, FusesPosesCapturedInsideTheOpenImuWindow) {
  // GIVEN a pose source without latency (a motion-capture-like stream): each pose arrives with
  // the IMU sample of its capture time, before the 4 ms window holding it has closed
  SensorSpec spec;
  spec.vio_latency_min = 0.0;
  spec.vio_latency_max = 0.0;
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), spec};
  const auto events = sensors.run(12.0);
  Estimator estimator{EstimatorParams()};

  // WHEN the estimator runs on it
  const RunResult run = runEstimator(estimator, sensors, events);

  // THEN such poses wait for their window and are all fused
  const auto pending = std::count(run.vio_outcomes.begin(), run.vio_outcomes.end(), VioOutcome::kPending);
  std::cout << "[ measured ] " << pending << " of " << run.vio_outcomes.size() << " poses waited for their window\n";
  EXPECT_GT(pending, 0);
  EXPECT_EQ(estimator.counters().rejectedTotal(), 0);
  // (the very last pose may still be waiting when the run ends)
  EXPECT_GE(estimator.counters().vio_fused + estimator.counters().initializations,
            static_cast<int64_t>(run.vio_outcomes.size()) - 1);
  EXPECT_LT(run.positionRms(4.0, 12.0), kPositionTarget);
  EXPECT_LT(run.attitudeRmsDeg(4.0, 12.0), kAttitudeTargetDeg);
}

}  // namespace
}  // namespace sdlqr::estimator::test
