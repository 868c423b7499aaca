// The bodyrate loop flying the test plant: rate step response, failsafe descent and landing,
// recovery, auto-disarm. Figures are printed and recorded as test properties.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

#include "flight_harness.hpp"

namespace sdlqr::test {
namespace {

using sdlqr::RejectReason;

constexpr double kDeg = M_PI / 180.0;

// Realistic sensor errors (the agreed simulator defaults at 1 kHz, biases at their bounds).
ImuErrors realisticImu(unsigned seed) {
  ImuErrors imu;
  imu.gyro_std = 0.016;
  imu.accel_std = 0.13;
  imu.gyro_bias = Vec3(0.02, -0.015, 0.01);
  imu.accel_bias = Vec3(0.1, -0.08, 0.1);
  imu.seed = seed;
  return imu;
}

struct StepResponse {
  double settling_time = 0.0;  // [s] last exit from the +-2 % band
  double overshoot = 0.0;      // [-] relative
  double rise_time = 0.0;      // [s] 10 % to 90 %
};

StepResponse analyze(const std::vector<double>& response, double target, double period) {
  StepResponse r;
  double t10 = -1.0, t90 = -1.0;
  for (size_t i = 0; i < response.size(); ++i) {
    const double t = period * static_cast<double>(i + 1);
    if (std::abs(response[i] - target) > 0.02 * std::abs(target)) r.settling_time = t;
    if (t10 < 0.0 && response[i] >= 0.1 * target) t10 = t;
    if (t90 < 0.0 && response[i] >= 0.9 * target) t90 = t;
  }
  r.overshoot = std::max(0.0, (*std::max_element(response.begin(), response.end()) - target) / target);
  r.rise_time = t90 - t10;
  return r;
}

// Hovering in RATE mode at 5 m, then a 1 rad/s step on one axis held for `duration`.
StepResponse rateStep(int axis, double duration) {
  FlightHarness h;
  h.plant.startHovering(5.0);
  h.tick();
  h.command(CommandType::kArm);
  const double hover = kGravity;
  for (int i = 0; i < 300; ++i) {
    if (i % 10 == 0) h.sendRate(Vec3::Zero(), hover);
    h.tick();
  }
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate);
  Vec3 step = Vec3::Zero();
  step[axis] = 1.0;
  std::vector<double> response;
  const int ticks = static_cast<int>(duration * 1000.0);
  for (int i = 0; i < ticks; ++i) {
    if (i % 10 == 0) h.sendRate(step, hover);
    h.tick();
    response.push_back(h.plant.body_rate[axis]);
  }
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate);
  return analyze(response, 1.0, 1e-3);
}

TEST(ClosedLoop, RollAndPitchRateStepSettleWithin80ms) {
  const char* names[] = {"roll", "pitch"};
  for (int axis = 0; axis < 2; ++axis) {
    const StepResponse r = rateStep(axis, 0.3);
    std::cout << names[axis] << " 1 rad/s step: rise " << 1e3 * r.rise_time << " ms, 2% settling "
              << 1e3 * r.settling_time << " ms, overshoot " << 100.0 * r.overshoot << " %\n";
    ::testing::Test::RecordProperty(std::string(names[axis]) + "_settling_ms", std::to_string(1e3 * r.settling_time));
    EXPECT_LE(r.settling_time, 0.080);
    EXPECT_LE(r.overshoot, 0.05);
  }
}

TEST(ClosedLoop, YawRateStepSettlesWithoutOvershoot) {
  // Rotor drag gives yaw about a tenth of the roll authority; the yaw loop is tuned slower.
  const StepResponse r = rateStep(2, 0.6);
  std::cout << "yaw 1 rad/s step: rise " << 1e3 * r.rise_time << " ms, 2% settling " << 1e3 * r.settling_time
            << " ms, overshoot " << 100.0 * r.overshoot << " %\n";
  ::testing::Test::RecordProperty("yaw_settling_ms", std::to_string(1e3 * r.settling_time));
  EXPECT_LE(r.settling_time, 0.4);
  EXPECT_LE(r.overshoot, 0.05);
}

TEST(ClosedLoop, HoversOnNoisyImuWithoutDisarmingOrFailsafe) {
  FlightHarness h(realisticImu(3));
  h.plant.thrust_scale = 1.05;
  h.holdFor(Vec3::Zero(), 2.0);  // disarmed on the ground: the filter learns its biases
  h.command(CommandType::kTakeoff);
  h.holdFor(Vec3(0.0, 0.0, 1.5), 8.0);
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate);
  // The stand-in controller has no integral: 5 % extra thrust leaves it about 0.12 m high.
  EXPECT_NEAR(h.plant.position.z(), 1.5, 0.2);
  EXPECT_EQ(h.loop.counters().auto_disarms, 0);
  EXPECT_EQ(h.loop.counters().failsafe_entries, 0);
  EXPECT_LT(h.plant.tilt(), 5.0 * kDeg);
  // The IMU-only estimate the failsafe would fly on.
  const double tilt_error = quat::tilt(quat::multiply(quat::conjugate(h.loop.status().attitude), h.plant.attitude));
  std::cout << "after 8 s hover: IMU-only tilt error " << tilt_error / kDeg << " deg, vertical velocity error "
            << h.loop.status().vertical_velocity - h.plant.velocity.z() << " m/s, learned hover thrust "
            << h.loop.status().hover_thrust << " m/s^2 (true " << kGravity / h.plant.thrust_scale << ")\n";
  EXPECT_LT(tilt_error, 2.0 * kDeg);
  EXPECT_NEAR(h.loop.status().hover_thrust, kGravity / h.plant.thrust_scale, 0.3);
}

struct FailsafeFlight {
  double engage_delay = -1.0;      // [s] from the last RATE_CMD's utime to FAILSAFE
  double max_tilt = 0.0;           // [rad] from the last command to the end
  double touchdown_speed = -1.0;   // [m/s]
  double disarm_delay = -1.0;      // [s] from touchdown to DISARMED
  double descent_rate = 0.0;       // [m/s] mean over the descent
  double tilt_after_1s = -1.0;     // [rad] one second after engaging
  MotorMode final_mode = MotorMode::kRate;
};

// Commands stop at the current time; flies on until disarmed or `limit` seconds pass.
FailsafeFlight flyFailsafe(FlightHarness& h, int64_t last_command_utime, double limit) {
  FailsafeFlight f;
  const int touchdowns_before = h.plant.touchdowns();
  const double start_height = h.plant.position.z();
  double engaged_at = -1.0, touchdown_at = -1.0;
  const int ticks = static_cast<int>(limit * 1000.0);
  for (int i = 0; i < ticks && h.loop.mode() != MotorMode::kDisarmed; ++i) {
    h.tick();
    f.max_tilt = std::max(f.max_tilt, h.plant.tilt());
    if (engaged_at < 0.0 && h.loop.mode() == MotorMode::kFailsafe) {
      engaged_at = h.seconds();
      f.engage_delay = 1e-6 * static_cast<double>(h.utime - last_command_utime);
    }
    if (engaged_at >= 0.0 && f.tilt_after_1s < 0.0 && h.seconds() - engaged_at >= 1.0) f.tilt_after_1s = h.plant.tilt();
    if (touchdown_at < 0.0 && h.plant.touchdowns() > touchdowns_before) {
      touchdown_at = h.seconds();
      f.touchdown_speed = h.plant.lastTouchdownSpeed();
    }
  }
  if (touchdown_at >= 0.0) {
    f.descent_rate = start_height / (touchdown_at - engaged_at);
    if (h.loop.mode() == MotorMode::kDisarmed) f.disarm_delay = h.seconds() - touchdown_at;
  }
  f.final_mode = h.loop.mode();
  return f;
}

void report(const char* name, const FailsafeFlight& f) {
  std::cout << name << ": engaged " << 1e3 * f.engage_delay << " ms after the last RATE_CMD, max tilt "
            << f.max_tilt / kDeg << " deg, mean descent " << f.descent_rate << " m/s, touchdown "
            << f.touchdown_speed << " m/s, disarmed " << 1e3 * f.disarm_delay << " ms after touchdown\n";
  ::testing::Test::RecordProperty(std::string(name) + "_touchdown_mps", std::to_string(f.touchdown_speed));
}

TEST(Failsafe, SilentRateCommandsLevelDescendAndDisarm) {
  for (unsigned seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    FlightHarness h(realisticImu(seed));
    h.plant.thrust_scale = 1.05;  // a fresh battery: the controller flies with less than g
    h.holdFor(Vec3::Zero(), 2.0);
    h.command(CommandType::kTakeoff);
    h.holdFor(Vec3(0.5, -0.3, 3.0), 6.0);
    ASSERT_EQ(h.loop.mode(), MotorMode::kRate);
    const int64_t last_command = h.utime - 10 * kImuPeriodUs + kImuPeriodUs;  // sent on the last 10 ms tick

    const FailsafeFlight f = flyFailsafe(h, last_command, 20.0);
    report("hover failsafe", f);
    EXPECT_GT(f.engage_delay, 0.0);
    EXPECT_LE(f.engage_delay, 0.2);
    EXPECT_LT(f.max_tilt, 30.0 * kDeg);
    EXPECT_GT(f.touchdown_speed, 0.0);
    EXPECT_LT(f.touchdown_speed, 1.0);
    EXPECT_EQ(f.final_mode, MotorMode::kDisarmed);
    EXPECT_GE(f.disarm_delay, 0.0);
    EXPECT_LE(f.disarm_delay, 2.0);
    EXPECT_EQ(h.loop.counters().failsafe_touchdowns, 1);
    EXPECT_EQ(h.last.thrust, Vec4::Zero());
    EXPECT_FALSE(h.last.armed);
  }
}

TEST(Failsafe, DisarmsPromptlyWhenTheTouchdownSpikeClips) {
  // A clipped spike integrates to less than the speed lost at touchdown; the velocity estimate
  // would keep "descending" on the ground for the whole leak time without the impact reset.
  ImuErrors imu = realisticImu(13);
  imu.accel_range = 20.0;
  FlightHarness h(imu);
  h.holdFor(Vec3::Zero(), 2.0);
  h.command(CommandType::kTakeoff);
  h.holdFor(Vec3(0.0, 0.0, 2.0), 5.0);
  const FailsafeFlight f = flyFailsafe(h, h.utime - 9 * kImuPeriodUs, 20.0);
  report("clipping accelerometer", f);
  EXPECT_LT(f.touchdown_speed, 1.0);
  EXPECT_EQ(f.final_mode, MotorMode::kDisarmed);
  EXPECT_GE(f.disarm_delay, 0.0);
  EXPECT_LE(f.disarm_delay, 1.0);
}

TEST(Failsafe, LevelsAVehicleLeftTiltedAndRolling) {
  FlightHarness h(realisticImu(7));
  h.holdFor(Vec3::Zero(), 2.0);
  h.command(CommandType::kTakeoff);
  h.holdFor(Vec3(0.0, 0.0, 2.5), 5.0);
  // The controller's last words: roll at 1.5 rad/s for 0.2 s, then silence.
  int64_t last_command = 0;
  for (int i = 0; i < 200; ++i) {
    if (i % 10 == 0) {
      h.sendRate(Vec3(1.5, 0.0, 0.0), kGravity);
      last_command = h.utime;
    }
    h.tick();
  }
  const double tilt_at_silence = h.plant.tilt();
  const FailsafeFlight f = flyFailsafe(h, last_command, 20.0);
  std::cout << "tilt when the commands stopped " << tilt_at_silence / kDeg << " deg, 1 s after engaging "
            << f.tilt_after_1s / kDeg << " deg\n";
  report("tilted failsafe", f);
  EXPECT_GT(tilt_at_silence, 15.0 * kDeg);
  EXPECT_LE(f.engage_delay, 0.2);
  EXPECT_LT(f.max_tilt, 30.0 * kDeg);
  EXPECT_GE(f.tilt_after_1s, 0.0);
  EXPECT_LT(f.tilt_after_1s, 3.0 * kDeg);
  EXPECT_GT(f.touchdown_speed, 0.0);
  EXPECT_LT(f.touchdown_speed, 1.0);
  EXPECT_EQ(f.final_mode, MotorMode::kDisarmed);
}

TEST(Failsafe, FreshRateCommandReturnsToRateMode) {
  FlightHarness h(realisticImu(11));
  h.plant.startHovering(3.0);
  h.tick();
  h.command(CommandType::kArm);
  h.holdFor(Vec3(0.0, 0.0, 3.0), 2.0);
  for (int i = 0; i < 300; ++i) h.tick();  // the controller dies for 0.3 s
  ASSERT_EQ(h.loop.mode(), MotorMode::kFailsafe);
  const double height_in_failsafe = h.plant.position.z();
  // The restarted controller publishes again.
  ASSERT_EQ(h.loop.setRateCommand(holdPosition(h.plant, Vec3(0.0, 0.0, 3.0), h.utime)), RejectReason::kNone);
  h.tick();
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate);
  EXPECT_EQ(h.loop.counters().failsafe_recoveries, 1);
  h.holdFor(Vec3(0.0, 0.0, 3.0), 4.0);
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate);
  EXPECT_NEAR(h.plant.position.z(), 3.0, 0.1);
  std::cout << "recovery: failsafe lost " << 3.0 - height_in_failsafe << " m before the controller returned\n";
}

TEST(Failsafe, StaleCommandsDoNotKeepTheLoopInRateMode) {
  // A controller that keeps publishing from a frozen estimate (estimator silent) is as good as none.
  FlightHarness h;
  h.plant.startHovering(3.0);
  h.tick();
  h.command(CommandType::kArm);
  h.holdFor(Vec3(0.0, 0.0, 3.0), 1.0);
  const int64_t frozen = h.utime;
  int engaged_after_ms = -1;
  for (int i = 0; i < 500; ++i) {
    if (i % 10 == 0) {
      RateCommand command = holdPosition(h.plant, Vec3(0.0, 0.0, 3.0), frozen);
      h.loop.setRateCommand(command);
    }
    h.tick();
    if (engaged_after_ms < 0 && h.loop.mode() == MotorMode::kFailsafe) engaged_after_ms = i + 1;
  }
  EXPECT_EQ(h.loop.mode(), MotorMode::kFailsafe);
  EXPECT_GT(engaged_after_ms, 0);
  EXPECT_LE(engaged_after_ms, 200);
  EXPECT_GT(h.loop.counters().rate_cmd_rejected[static_cast<size_t>(RejectReason::kStale)], 0);
}

TEST(Landing, ControllerLandingAutoDisarmsOnTheGround) {
  FlightHarness h(realisticImu(5));
  h.holdFor(Vec3::Zero(), 2.0);
  h.command(CommandType::kTakeoff);
  h.holdFor(Vec3(0.0, 0.0, 1.0), 4.0);
  ASSERT_EQ(h.loop.mode(), MotorMode::kRate);
  // Landing as a controller does it: a target below the ground pulls the thrust well under hover.
  double touchdown_at = -1.0, disarmed_at = -1.0;
  const int touchdowns_before = h.plant.touchdowns();
  for (int i = 0; i < 8000 && disarmed_at < 0.0; ++i) {
    if (i % 10 == 0) {
      Vec3 target = h.plant.position;
      target.z() = h.plant.position.z() > 0.05 ? h.plant.position.z() - 0.4 : -1.0;
      h.loop.setRateCommand(holdPosition(h.plant, target, h.utime));
    }
    h.tick();
    if (touchdown_at < 0.0 && h.plant.touchdowns() > touchdowns_before) touchdown_at = h.seconds();
    if (h.loop.mode() == MotorMode::kDisarmed) disarmed_at = h.seconds();
  }
  ASSERT_GT(touchdown_at, 0.0);
  ASSERT_GT(disarmed_at, 0.0);
  std::cout << "controller landing: touchdown " << h.plant.lastTouchdownSpeed() << " m/s, auto-disarm "
            << 1e3 * (disarmed_at - touchdown_at) << " ms after touchdown\n";
  EXPECT_EQ(h.loop.counters().auto_disarms, 1);
  EXPECT_GE(disarmed_at - touchdown_at, 1.0);  // landed_time of rest first
  EXPECT_LE(disarmed_at - touchdown_at, 2.0);
}

TEST(Landing, ControllerFallingSilentAfterLandingDisarmsWithoutFailsafe) {
  // The LQR controller stops publishing once it considers itself landed.
  FlightHarness h(realisticImu(9));
  h.holdFor(Vec3::Zero(), 2.0);
  h.command(CommandType::kTakeoff);
  h.holdFor(Vec3(0.0, 0.0, 1.0), 3.0);
  const int touchdowns_before = h.plant.touchdowns();
  double touchdown_at = -1.0;
  for (int i = 0; i < 8000; ++i) {
    const bool publishing = touchdown_at < 0.0 || h.seconds() - touchdown_at < 0.4;
    if (publishing && i % 10 == 0) {
      Vec3 target = h.plant.position;
      target.z() = h.plant.position.z() > 0.05 ? h.plant.position.z() - 0.4 : -1.0;
      h.loop.setRateCommand(holdPosition(h.plant, target, h.utime));
    }
    h.tick();
    if (touchdown_at < 0.0 && h.plant.touchdowns() > touchdowns_before) touchdown_at = h.seconds();
    if (h.loop.mode() == MotorMode::kDisarmed) break;
  }
  ASSERT_GT(touchdown_at, 0.0);
  EXPECT_EQ(h.loop.mode(), MotorMode::kDisarmed);
  EXPECT_LT(h.seconds() - touchdown_at, 0.4 + 0.15);
  EXPECT_EQ(h.loop.counters().failsafe_entries, 0);
  EXPECT_EQ(h.loop.counters().auto_disarms, 1);
}

TEST(Landing, LowThrustInTheAirDoesNotDisarm) {
  // Diving with thrust far below hover: the accelerometer reads the low thrust, not g.
  FlightHarness h;
  h.plant.startHovering(20.0);
  h.tick();
  h.command(CommandType::kArm);
  for (int i = 0; i < 1500; ++i) {
    if (i % 10 == 0) h.sendRate(Vec3::Zero(), 0.4 * kGravity);
    h.tick();
  }
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate);
  EXPECT_EQ(h.loop.counters().auto_disarms, 0);
  EXPECT_GT(h.plant.position.z(), 5.0);
}

TEST(Landing, AHardClimbDoesNotMakeTheSteadyClimbAfterItLookLanded) {
  // 3 s at 1.5 g, then thrust g: a steady climb, where the accelerometer reads g as on the ground
  // and the hover thrust learned in the hard climb (~13.6 m/s^2) makes g look "below hover". The
  // landing test froze that estimate and disarmed the vehicle in the air 1 s later (the same after
  // the agile circle); the rotors explain all the IMU reads, so it is not landed. No rotor drag
  // here, or it would slow the climb and the reading.
  VehicleParams vehicle;
  vehicle.rotor_drag.setZero();
  FlightHarness h(ImuErrors(), lowlevel::LowlevelParams(), vehicle);
  h.plant.startHovering(20.0);
  h.tick();
  h.command(CommandType::kArm);
  double highest_estimate = 0.0;
  for (int i = 0; i < 5000; ++i) {
    if (i % 10 == 0) h.sendRate(Vec3::Zero(), (i < 3000 ? 1.5 : 1.0) * kGravity);
    h.tick();
    highest_estimate = std::max(highest_estimate, h.loop.status().hover_thrust);
  }
  EXPECT_GT(highest_estimate, kGravity / h.loop.params().ground_detector.landed_thrust_ratio)
      << "the climb no longer raises the estimate past the landing test: the test proves nothing";
  EXPECT_EQ(h.loop.mode(), MotorMode::kRate) << "not flying at the end";
  EXPECT_EQ(h.loop.counters().auto_disarms, 0) << "disarmed in the air";
  EXPECT_GT(h.plant.velocity.z(), 10.0);
}

}  // namespace
}  // namespace sdlqr::test
