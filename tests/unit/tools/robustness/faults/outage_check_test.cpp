// The measurements of the kill -9 tests, on synthetic flight logs with known answers.

#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/faults/outage_check.hpp"

namespace sdlqr::faults {
namespace {

// Simulation time t [s] is received at wall time kWall0 + t (a real-time flight).
constexpr int64_t kWall0 = 1'700'000'000'000'000;
int64_t us(double t) { return static_cast<int64_t>(std::llround(t * 1e6)); }
int64_t wall(double t) { return kWall0 + us(t); }

template <class T>
void add(logger::Series<T>& series, T message, double t) {
  message.utime = us(t);
  series.messages.push_back(message);
  series.receive_utime.push_back(wall(t));
}

SimTruth truthAt(const Vec3& p, const Vec3& v = Vec3::Zero(), double tilt_rad = 0.0, bool on_ground = false) {
  SimTruth truth;
  truth.position = p;
  truth.velocity = v;
  truth.orientation = Quat(std::cos(0.5 * tilt_rad), std::sin(0.5 * tilt_rad), 0.0, 0.0);
  truth.on_ground = on_ground;
  return truth;
}

MotorCommand motor(MotorMode mode) {
  MotorCommand m;
  m.mode = mode;
  return m;
}

TEST(OutageCheck, SimTimeAtWallIsTheFirstTruthReceivedThen) {
  logger::FlightLog log;
  for (int i = 0; i < 100; ++i) add(log.sim_truth, truthAt(Vec3::Zero()), 0.01 * i);
  EXPECT_EQ(simTimeAtWall(log, wall(0.5)), us(0.5));
  EXPECT_EQ(simTimeAtWall(log, wall(0.505)), us(0.51));
  EXPECT_EQ(simTimeAtWall(log, wall(2.0)), -1);
}

TEST(OutageCheck, GainsOutageFindsTheHoverKAfterTheTimeoutAndTheResume) {
  logger::FlightLog log;
  // GAINS at 10 Hz until 5.0 s, killed at 5.05 s, restarted at 15 s, first new GAINS at 15.3 s.
  for (double t = 0.0; t <= 5.0 + 1e-9; t += 0.1) add(log.gains, GainSet{}, t);
  for (double t = 15.3; t <= 20.0; t += 0.1) add(log.gains, GainSet{}, t);
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.01 * i;
    RateCommand command;
    command.gains_seq = 1;
    if (t > 6.0 && t < 15.3) {
      command.gains_status = GainsFreshness::kFallback;
      command.gains_seq = -1;
    } else if (t > 5.3 && t <= 6.0) {
      command.gains_status = GainsFreshness::kStale;
    }
    add(log.rate_command, command, t);
  }
  for (int i = 0; i <= 200; ++i) add(log.sim_truth, truthAt(Vec3(0, 0, 1)), 0.1 * i);
  // The restarted solver's first HEARTBEAT at 15.2 s (it took 0.2 s to start), GAINS 0.1 s later.
  logger::HeartbeatRecord up;
  up.process = "sdlqr-gains";
  add(log.heartbeat, up, 15.2);
  const GainsOutage g = measureGainsOutage(log, wall(5.05), wall(15.0), 1.0);
  EXPECT_NEAR(g.resume_after_up_s, 0.1, 1e-6);
  EXPECT_EQ(g.last_gains_utime, us(5.0));
  EXPECT_EQ(g.first_fallback_utime, us(6.01));
  EXPECT_NEAR(g.resume_delay_s, 0.3, 1e-6);
  EXPECT_EQ(g.fallback_commands, 899);  // 6.01 .. 14.99 s
  EXPECT_EQ(g.late_non_fallback_commands, 0);
  EXPECT_GT(g.fresh_commands_after_resume, 400);

  // A solver that is up but does not solve for a second is caught in simulation time, whatever
  // its start-up took.
  logger::FlightLog slow = log;
  slow.heartbeat.messages.clear();
  slow.heartbeat.receive_utime.clear();
  add(slow.heartbeat, up, 14.3);
  EXPECT_NEAR(measureGainsOutage(slow, wall(5.05), wall(14.0), 1.0).resume_after_up_s, 1.0, 1e-6);

  // The last GAINS, sent at 5.0 s before the kill at 5.05 s, reaching the recorder only at 5.15 s
  // (a loaded machine): the fallback is still judged from it, not from the one before (which
  // found the controller's switch at 6.01 s nine ticks late).
  logger::FlightLog late = log;
  for (size_t i = 0; i < late.gains.size(); ++i) {
    if (late.gains.messages[i].utime == us(5.0)) late.gains.receive_utime[i] = wall(5.15);
  }
  const GainsOutage l = measureGainsOutage(late, wall(5.05), wall(15.0), 1.0);
  EXPECT_EQ(l.last_gains_utime, us(5.0));
  EXPECT_EQ(l.late_non_fallback_commands, 0);

  // A controller that never falls back is caught.
  logger::FlightLog stuck = log;
  for (RateCommand& command : stuck.rate_command.messages) command.gains_status = GainsFreshness::kStale;
  const GainsOutage s = measureGainsOutage(stuck, wall(5.05), wall(15.0), 1.0);
  EXPECT_EQ(s.fallback_commands, 0);
  EXPECT_GT(s.late_non_fallback_commands, 800);
}

Command takeoff(int64_t seq) {
  Command c;
  c.seq = seq;
  c.command = CommandType::kTakeoff;
  c.position = Vec3(0, 0, 1);
  return c;
}

// Hover at 1 m, the estimator killed at 8.002 s and restarted at 13 s; the failsafe descends from
// 8.1 s and the vehicle touches down at 10.1 s; the mission sends its TAKEOFF at 1 s and re-sends
// it every second until 20 s. `rearm_at`: the motors are armed again from then on (never: < 0).
logger::FlightLog estimatorOutageFlight(double rearm_at = -1.0) {
  logger::FlightLog log;
  for (double t = 0.0; t <= 8.0 + 1e-9; t += 0.004) add(log.state_estimate, StateEstimate{}, t);
  for (int i = 0; i <= 20000; ++i) {
    const double t = 0.001 * i;
    MotorCommand m = motor(t < 8.12 ? MotorMode::kRate : (t < 10.5 ? MotorMode::kFailsafe : MotorMode::kDisarmed));
    if (rearm_at >= 0.0 && t >= rearm_at) m = motor(MotorMode::kIdle);
    m.armed = m.mode != MotorMode::kDisarmed;
    add(log.motor_command, m, t);
  }
  for (int second = 1; second <= 20; ++second) add(log.command, takeoff(1), second);
  // Descends from 1 m at 0.5 m/s from 8.1 s, tilting up to 12 degrees, touches down at 10.1 s.
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.01 * i;
    const double z = t < 8.1 ? 1.0 : std::max(0.0, 1.0 - 0.5 * (t - 8.1));
    const bool ground = t >= 8.1 && z <= 0.0;
    const double tilt = (t > 8.5 && t < 8.6) ? 12.0 * M_PI / 180.0 : 0.0;
    add(log.sim_truth, truthAt(Vec3(0, 0, z), ground ? Vec3::Zero() : Vec3(0, 0, t < 8.1 ? 0.0 : -0.5), tilt, ground),
        t);
  }
  return log;
}

TEST(OutageCheck, EstimatorOutageMeasuresFailsafeDelayTiltAndTouchdown) {
  const EstimatorOutage e = measureEstimatorOutage(estimatorOutageFlight(), wall(8.002), wall(13.0));
  EXPECT_EQ(e.last_estimate_utime, us(8.0));
  EXPECT_EQ(e.failsafe_utime, us(8.12));
  EXPECT_NEAR(e.failsafe_delay_s, 0.12, 1e-9);
  EXPECT_NEAR(e.max_tilt_deg, 12.0, 1e-6);
  EXPECT_EQ(e.touchdown_utime, us(10.1));
  EXPECT_NEAR(e.touchdown_speed, 0.5, 1e-12);
  EXPECT_TRUE(e.disarmed_after_touchdown);
  EXPECT_EQ(e.disarm_utime, us(10.5));
  EXPECT_EQ(e.rearmed_commands, 0);
  EXPECT_EQ(e.resent_takeoffs_after_restart, 8);  // 13 .. 20 s
  EXPECT_FALSE(e.crashed);
  EXPECT_TRUE(allOk(judgeEstimatorOutage(e, EstimatorLimits{})));
}

TEST(OutageCheck, AVehicleTheFailsafeLandedThatArmsAgainFails) {
  // Re-armed by the TAKEOFF re-sent at 15 s, two seconds after the estimator's restart.
  const EstimatorOutage e = measureEstimatorOutage(estimatorOutageFlight(15.0), wall(8.002), wall(13.0));
  EXPECT_TRUE(e.disarmed_after_touchdown);
  EXPECT_EQ(e.rearmed_commands, 5001);  // 15.000 .. 20.000 s at 1 kHz
  const std::vector<Finding> findings = judgeEstimatorOutage(e, EstimatorLimits{});
  ASSERT_EQ(findings.size(), 5u);
  EXPECT_TRUE(findings[3].ok) << findings[3].text;   // it did disarm before the restart
  EXPECT_FALSE(findings[4].ok) << findings[4].text;  // and armed again after it
}

TEST(OutageCheck, AnOutageCheckWithoutAReSentTakeoffHasTestedNothingAndFails) {
  logger::FlightLog log = estimatorOutageFlight();
  log.command = {};
  add(log.command, takeoff(1), 1.0);
  const EstimatorOutage e = measureEstimatorOutage(log, wall(8.002), wall(13.0));
  EXPECT_EQ(e.resent_takeoffs_after_restart, 0);
  EXPECT_FALSE(judgeEstimatorOutage(e, EstimatorLimits{}).back().ok);
}

TEST(OutageCheck, AVehicleNeverDisarmedOnTheGroundFails) {
  logger::FlightLog log = estimatorOutageFlight();
  for (MotorCommand& m : log.motor_command.messages) {
    if (m.mode == MotorMode::kDisarmed) m = motor(MotorMode::kFailsafe);
  }
  const EstimatorOutage e = measureEstimatorOutage(log, wall(8.002), wall(13.0));
  EXPECT_FALSE(e.disarmed_after_touchdown);
  const std::vector<Finding> findings = judgeEstimatorOutage(e, EstimatorLimits{});
  EXPECT_FALSE(findings[3].ok) << findings[3].text;
  EXPECT_FALSE(allOk(findings));
}

TEST(OutageCheck, ControllerOutageMeasuresTheGapAndTheReturnThatLasts) {
  logger::FlightLog log;
  const Vec3 setpoint(0, 0, 1);
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.01 * i;
    if (t <= 8.0 + 1e-9 || t >= 9.4 - 1e-9) add(log.rate_command, RateCommand{}, t);
  }
  for (int i = 0; i <= 20000; ++i) {
    const double t = 0.001 * i;
    add(log.motor_command, motor(t > 8.1 && t < 9.4 ? MotorMode::kFailsafe : MotorMode::kRate), t);
  }
  // Sinks to 0.6 m in the gap (tilt 3 deg), comes back inside 0.1 m at 10.0 s, overshoots out of
  // it for 10.4-10.6 s, inside for good from 10.6 s.
  for (int i = 0; i <= 2000; ++i) {
    const double t = 0.01 * i;
    double z = 1.0;
    if (t > 8.0 && t <= 9.4) z = 1.0 - 0.4 * (t - 8.0) / 1.4;
    if (t > 9.4 && t < 10.0) z = 0.6 + 0.35 * (t - 9.4) / 0.6;
    if (t >= 10.4 && t < 10.6) z = 1.15;
    add(log.sim_truth, truthAt(Vec3(0, 0, z), Vec3::Zero(), t > 8.0 && t < 9.4 ? 3.0 * M_PI / 180.0 : 0.0), t);
  }
  const ControllerOutage c = measureControllerOutage(log, wall(8.005), wall(9.35), setpoint, 0.1, us(20.0));
  EXPECT_EQ(c.last_command_utime, us(8.0));
  EXPECT_EQ(c.failsafe_utime, us(8.101));
  EXPECT_EQ(c.resumed_utime, us(9.4));
  EXPECT_NEAR(c.max_gap_tilt_deg, 3.0, 1e-6);
  EXPECT_NEAR(c.gap_height_loss, 0.4, 1e-9);
  EXPECT_NEAR(c.error_at_resume, 0.4 - 0.35 * 0.01 / 0.6, 1e-9);
  EXPECT_NEAR(c.return_time_s, 10.6 - 9.4, 1e-9);
  // Never back: -1.
  const ControllerOutage never = measureControllerOutage(log, wall(8.005), wall(9.35), Vec3(0, 0, 2), 0.1, us(20.0));
  EXPECT_EQ(never.return_time_s, -1.0);
}

}  // namespace
}  // namespace sdlqr::faults
