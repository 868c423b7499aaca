// The bridge's core against a scripted PX4 (bridge_test_support.hpp): the offboard handshake as
// PX4 requires it, commands resent until their ACK, setpoints in FRD with PX4's thrust, the
// failsafes, and bad input that never reaches the bus. Time is passed in: no clock, no sleep.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bridge_test_support.hpp"

namespace sdlqr::px4 {
namespace {

using test::take;
namespace cmd = mavlink::mav_cmd;
constexpr double kGravity = 9.81;
constexpr uint8_t kOnGround = mavlink::mav_landed_state::kOnGround;
constexpr uint8_t kInAir = mavlink::mav_landed_state::kInAir;

class BridgeTest : public ::testing::Test {
 protected:
  BridgeTest()
      : endpoint_({1, kOnboardComputerComponent}, sink_, [] { return uint64_t{0}; }),
        bridge_(BridgeParams(), kGravity, ValidationLimits(), endpoint_),
        bus_(test::busSink(published_)),
        px4_(bridge_, bus_) {}

  // One 10 ms step of PX4 (odometry at 100 Hz, heartbeat and landed state at 10 Hz) and the bridge.
  void step(bool armed, FlightMode mode, uint8_t landed, double height = 0.0) {
    now_ += 0.01;
    bridge_.onWallTime(now_);
    utime_ += 10000;
    if (std::lround(now_ * 100) % 10 == 0) {
      px4_.heartbeat(armed, mode);
      px4_.landed(landed);
    }
    px4_.odometry(utime_, height);
  }
  void run(double seconds, bool armed, FlightMode mode, uint8_t landed, double height = 0.0) {
    for (int i = 0; i < std::lround(seconds / 0.01); ++i) step(armed, mode, landed, height);
  }
  // Connects and answers the three stream requests.
  void connect(bool landed_state_known = true) {
    bridge_.onWallTime(now_);
    px4_.heartbeat(false, FlightMode{});
    if (landed_state_known) px4_.landed(kOnGround);
    px4_.odometry(utime_);
    for (int i = 0; i < 3; ++i) px4_.ack(cmd::kSetMessageInterval, mavlink::mav_result::kAccepted);
    take(sink_);
  }
  Command command(CommandType type) {
    Command c;
    c.utime = utime_;
    c.seq = ++command_seq_;
    c.command = type;
    c.position = Vec3(0.0, 0.0, 1.0);
    return c;
  }
  RateCommand rateCommand(const Vec3& rate, double thrust) {
    RateCommand r;
    r.utime = utime_;
    r.seq = ++rate_seq_;
    r.body_rate = rate;
    r.thrust = thrust;
    return r;
  }
  int64_t counter(const char* name) const { return bridge_.health().counter(name); }

  test::CaptureSink sink_;
  MavlinkEndpoint endpoint_;
  BridgeCore bridge_;
  test::BusCapture published_;
  OutboxTo<decltype(test::busSink(std::declval<test::BusCapture&>()))> bus_;
  test::ScriptedPx4 px4_;
  double now_ = 0.0;
  int64_t utime_ = 1'000'000;
  int64_t command_seq_ = 0, rate_seq_ = 0;
};

TEST_F(BridgeTest, AsksForItsStreamsAtTheRatesItNeeds) {
  bridge_.onWallTime(0.0);
  px4_.heartbeat(false, FlightMode{});
  auto sent = take(sink_);
  ASSERT_EQ(sent.commands.size(), 1u);  // one command in flight at a time
  EXPECT_EQ(sent.commands[0].command, cmd::kSetMessageInterval);
  EXPECT_EQ(sent.commands[0].param1, static_cast<float>(mavlink::Odometry::kId));
  EXPECT_EQ(sent.commands[0].param2, 4000.0f);  // 250 Hz
  px4_.ack(cmd::kSetMessageInterval, mavlink::mav_result::kAccepted);
  sent = take(sink_);
  ASSERT_EQ(sent.commands.size(), 1u);
  EXPECT_EQ(sent.commands[0].param1, static_cast<float>(mavlink::HighresImu::kId));
  EXPECT_EQ(sent.heartbeats.size(), 0u);
  EXPECT_EQ(sent.commands[0].target_system, 1);
}

TEST_F(BridgeTest, ItsOwnHeartbeatIsAnOnboardControllerOnceASecond) {
  connect();
  run(3.05, false, FlightMode{}, kOnGround);
  const auto sent = take(sink_);
  ASSERT_EQ(sent.heartbeats.size(), 3u);  // at 1, 2 and 3 s (the first went out at 0 s)
  EXPECT_EQ(sent.heartbeats[0].type, mavlink::mav_type::kOnboardController);
  EXPECT_EQ(sent.heartbeats[0].autopilot, mavlink::mav_autopilot::kInvalid);
  EXPECT_EQ(sent.heartbeats[0].mavlink_version, 3);
}

TEST_F(BridgeTest, HandshakeStreamsOverASecondThenAsksOffboardThenArms) {
  connect();
  bridge_.onCommand(command(CommandType::kArm));
  double first_setpoint = -1.0, offboard_asked = -1.0;
  for (int i = 0; i < 200 && offboard_asked < 0; ++i) {
    step(false, FlightMode{}, kOnGround);
    const auto sent = take(sink_);
    if (!sent.setpoints.empty() && first_setpoint < 0) first_setpoint = now_;
    for (const auto& s : sent.setpoints) {
      EXPECT_EQ(s.thrust, 0.0f);  // on the ground, no RATE_CMD: zero thrust
      EXPECT_EQ(s.type_mask, 128);
    }
    for (const auto& c : sent.commands) {
      if (c.command == cmd::kDoSetMode) {
        offboard_asked = now_;
        EXPECT_EQ(c.param1, 1.0f);  // MAV_MODE_FLAG_CUSTOM_MODE_ENABLED
        EXPECT_EQ(c.param2, 6.0f);  // PX4's OFFBOARD
      }
    }
  }
  ASSERT_GE(first_setpoint, 0.0);
  ASSERT_GE(offboard_asked, 0.0);
  EXPECT_GE(offboard_asked - first_setpoint, 1.0);  // PX4: the stream runs before the switch
  EXPECT_EQ(bridge_.state(), BridgeState::kHandshake);
  px4_.ack(cmd::kDoSetMode, mavlink::mav_result::kAccepted);
  run(0.1, false, kOffboardMode, kOnGround);
  auto sent = take(sink_);
  ASSERT_FALSE(sent.commands.empty());
  EXPECT_EQ(sent.commands[0].command, cmd::kComponentArmDisarm);
  EXPECT_EQ(sent.commands[0].param1, 1.0f);
  px4_.ack(cmd::kComponentArmDisarm, mavlink::mav_result::kAccepted);
  run(0.1, true, kOffboardMode, kOnGround);
  EXPECT_EQ(bridge_.state(), BridgeState::kFlying);
  EXPECT_EQ(counter("px4.offboard.asked"), 1);
  EXPECT_EQ(counter("px4.arm.asked"), 1);
}

TEST_F(BridgeTest, WithoutASetpointStreamOffboardIsNeverAsked) {
  connect(false);
  bridge_.onCommand(command(CommandType::kArm));
  // PX4 never says the vehicle is on the ground (no EXTENDED_SYS_STATE): no zero-thrust stream, no
  // RATE_CMD either, so no proof of life and no OFFBOARD request.
  for (int i = 0; i < 300; ++i) {
    now_ += 0.01;
    utime_ += 10000;
    bridge_.onWallTime(now_);
    if (i % 10 == 0) px4_.heartbeat(false, FlightMode{});
    px4_.odometry(utime_);
  }
  const auto sent = take(sink_);
  EXPECT_TRUE(sent.setpoints.empty());
  for (const auto& c : sent.commands) EXPECT_NE(c.command, cmd::kDoSetMode);
  EXPECT_EQ(bridge_.state(), BridgeState::kStreaming);
}

TEST_F(BridgeTest, AnUnansweredCommandIsResentThenTimesOutAndIsAskedAgainLater) {
  connect();
  bridge_.onCommand(command(CommandType::kArm));
  std::vector<double> sends;
  for (int i = 0; i < 500; ++i) {
    step(false, FlightMode{}, kOnGround);
    for (const auto& c : take(sink_).commands) {
      if (c.command == cmd::kDoSetMode) sends.push_back(now_);
    }
  }
  ASSERT_GE(sends.size(), 9u);  // 8 sends, a time-out, the retry 1 s later
  for (int i = 1; i < 8; ++i) EXPECT_NEAR(sends[i] - sends[i - 1], 0.25, 0.011) << i;
  // handshake_retry_s after the time-out; each of the two boundaries may fall one 10 ms step later
  EXPECT_NEAR(sends[8] - sends[7], 0.25 + 1.0, 0.021);
  EXPECT_EQ(counter("px4.commands.timed_out"), 1);
  EXPECT_EQ(counter("px4.offboard.refused"), 1);
}

TEST_F(BridgeTest, ARefusedOffboardIsAskedAgainAfterTheRetryTime) {
  connect();
  bridge_.onCommand(command(CommandType::kArm));
  double refused_at = -1.0, asked_again = -1.0;
  for (int i = 0; i < 400 && asked_again < 0; ++i) {
    step(false, FlightMode{}, kOnGround);
    for (const auto& c : take(sink_).commands) {
      if (c.command != cmd::kDoSetMode) continue;
      if (refused_at < 0) {
        px4_.ack(cmd::kDoSetMode, mavlink::mav_result::kTemporarilyRejected);
        refused_at = now_;
      } else if (c.confirmation == 0) {
        asked_again = now_;
      }
    }
  }
  ASSERT_GE(asked_again, 0.0);
  EXPECT_NEAR(asked_again - refused_at, 1.0, 0.02);
  EXPECT_EQ(counter("px4.offboard.refused"), 1);
  EXPECT_NE(bridge_.health().lastError().find("MAV_RESULT 1"), std::string::npos);
}

TEST_F(BridgeTest, RateCommandBecomesFrdRatesAndPx4sThrust) {
  connect();
  step(false, FlightMode{}, kOnGround);
  take(sink_);
  // A command computed from an estimate 60 ms older than the newest: stale, not sent.
  RateCommand stale = rateCommand(Vec3::Zero(), kGravity);
  stale.utime = utime_ - 60000;
  EXPECT_EQ(bridge_.onRateCommand(stale), RejectReason::kStale);
  EXPECT_TRUE(take(sink_).setpoints.empty());
  EXPECT_EQ(bridge_.onRateCommand(rateCommand(Vec3(0.1, 0.2, 0.3), kGravity)), RejectReason::kNone);
  const auto sent = take(sink_);
  ASSERT_EQ(sent.setpoints.size(), 1u);
  const auto& s = sent.setpoints[0];
  EXPECT_FLOAT_EQ(s.body_roll_rate, 0.1f);
  EXPECT_FLOAT_EQ(s.body_pitch_rate, -0.2f);
  EXPECT_FLOAT_EQ(s.body_yaw_rate, -0.3f);
  EXPECT_FLOAT_EQ(s.thrust, static_cast<float>(ThrustMap().hover_throttle));  // c = g: hover
  EXPECT_EQ(s.type_mask, mavlink::attitude_target_typemask::kAttitudeIgnore);
  EXPECT_EQ(s.q[0], 1.0f);
  EXPECT_EQ(s.target_system, 1);
  EXPECT_EQ(s.target_component, 1);
  RateCommand older = rateCommand(Vec3::Zero(), kGravity);
  older.utime = utime_ - 5000;
  EXPECT_EQ(bridge_.onRateCommand(older), RejectReason::kTimeBackwards);
  RateCommand nan = rateCommand(Vec3(std::nan(""), 0, 0), kGravity);
  EXPECT_EQ(bridge_.onRateCommand(nan), RejectReason::kNonFinite);
  EXPECT_TRUE(take(sink_).setpoints.empty());
}

TEST_F(BridgeTest, ASilentControllerInTheAirStopsTheStreamForPx4sFailsafe) {
  connect();
  bridge_.onCommand(command(CommandType::kTakeoff));
  for (int i = 0; i < 50; ++i) {
    step(true, kOffboardMode, kInAir, 1.0);
    bridge_.onRateCommand(rateCommand(Vec3::Zero(), kGravity));
  }
  take(sink_);
  run(1.0, true, kOffboardMode, kInAir, 1.0);  // the controller is gone
  EXPECT_TRUE(take(sink_).setpoints.empty());  // no zero thrust in the air, nothing at all
  EXPECT_EQ(counter("failsafe.controller_silent"), 1);
  EXPECT_EQ(bridge_.health().state(), ProcessState::kDegraded);
}

TEST_F(BridgeTest, ALostLinkIsTheStacksFailsafeAndRecovers) {
  connect();
  bridge_.onCommand(command(CommandType::kTakeoff));
  run(0.2, true, kOffboardMode, kInAir, 1.0);
  for (int i = 0; i < 60; ++i) {  // 0.6 s of silence from PX4: no ODOMETRY for over 0.5 s
    now_ += 0.01;
    bridge_.onWallTime(now_);
  }
  EXPECT_EQ(bridge_.state(), BridgeState::kLinkLost);
  EXPECT_EQ(bridge_.health().state(), ProcessState::kFailsafe);
  EXPECT_EQ(counter("failsafe.no_odometry"), 1);
  EXPECT_EQ(counter("failsafe.no_heartbeat"), 0);  // PX4's 1 Hz heartbeat: lost after 3 s
  EXPECT_EQ(bridge_.onRateCommand(rateCommand(Vec3::Zero(), kGravity)), RejectReason::kRefused);
  take(sink_);
  // PX4 comes back in Hold: it left OFFBOARD during our outage, so the bridge streams and asks again.
  utime_ += 600000;
  run(0.3, true, kHoldMode, kInAir, 1.0);
  for (int i = 0; i < 3; ++i) px4_.ack(cmd::kSetMessageInterval, mavlink::mav_result::kAccepted);
  EXPECT_EQ(counter("px4.offboard.left_in_link_loss"), 1);
  EXPECT_EQ(counter("px4.offboard.left_by_autopilot"), 0);
  int asked = 0, streams = 0;
  for (int i = 0; i < 150; ++i) {
    step(true, kHoldMode, kInAir, 1.0);
    bridge_.onRateCommand(rateCommand(Vec3::Zero(), kGravity));
    for (const auto& c : take(sink_).commands) {
      asked += c.command == cmd::kDoSetMode ? 1 : 0;
      streams += c.command == cmd::kSetMessageInterval ? 1 : 0;
    }
  }
  EXPECT_GE(streams, 1);  // the streams asked for again (PX4 may have rebooted)
  EXPECT_GE(asked, 1);
}

TEST_F(BridgeTest, Px4LeavingOffboardWhileTheLinkHeldIsFinalUntilTheMissionAsksAgain) {
  connect();
  bridge_.onCommand(command(CommandType::kTakeoff));
  for (int i = 0; i < 30; ++i) {
    step(true, kOffboardMode, kInAir, 1.0);
    bridge_.onRateCommand(rateCommand(Vec3::Zero(), kGravity));
  }
  for (int i = 0; i < 300; ++i) {  // a pilot switched to Hold; the controller streams on
    step(true, kHoldMode, kInAir, 1.0);
    bridge_.onRateCommand(rateCommand(Vec3::Zero(), kGravity));
    for (const auto& c : take(sink_).commands) EXPECT_NE(c.command, cmd::kDoSetMode);
  }
  EXPECT_EQ(bridge_.state(), BridgeState::kTakenOver);
  EXPECT_EQ(counter("px4.offboard.left_by_autopilot"), 1);
  bridge_.onCommand(command(CommandType::kTakeoff));  // the mission asks again
  int asked = 0;
  for (int i = 0; i < 30; ++i) {
    step(true, kHoldMode, kInAir, 1.0);
    bridge_.onRateCommand(rateCommand(Vec3::Zero(), kGravity));
    for (const auto& c : take(sink_).commands) asked += c.command == cmd::kDoSetMode && c.confirmation == 0 ? 1 : 0;
  }
  EXPECT_EQ(asked, 1);
}

TEST_F(BridgeTest, LandDisarmsOncePx4ReportsTheVehicleOnTheGround) {
  connect();
  bridge_.onCommand(command(CommandType::kTakeoff));
  run(0.2, true, kOffboardMode, kInAir, 1.0);
  bridge_.onCommand(command(CommandType::kLand));
  run(1.0, true, kOffboardMode, kInAir, 0.5);
  for (const auto& c : take(sink_).commands) EXPECT_NE(c.command, cmd::kComponentArmDisarm);
  run(0.2, true, kOffboardMode, kOnGround, 0.0);
  const auto sent = take(sink_);
  ASSERT_FALSE(sent.commands.empty());
  EXPECT_EQ(sent.commands[0].command, cmd::kComponentArmDisarm);
  EXPECT_EQ(sent.commands[0].param1, 0.0f);
  px4_.ack(cmd::kComponentArmDisarm, mavlink::mav_result::kAccepted);
  run(0.2, false, kOffboardMode, kOnGround);
  EXPECT_EQ(bridge_.intent(), FlightIntent::kIdle);
  EXPECT_EQ(bridge_.state(), BridgeState::kStandby);
}

TEST_F(BridgeTest, OdometryBecomesStateEstimateAndTheVehiclesClock) {
  connect();
  published_ = {};
  run(0.1, false, FlightMode{}, kOnGround, 2.0);
  ASSERT_EQ(published_.estimates.size(), 10u);
  EXPECT_EQ(published_.estimates.back().utime, utime_);
  EXPECT_NEAR(published_.estimates.back().position[2], 2.0, 1e-6);  // NED z -2 is 2 m up
  EXPECT_EQ(published_.estimates.back().seq, published_.estimates.front().seq + 9);
  ASSERT_EQ(published_.clock.size(), 10u);  // one tick per 10 ms of PX4's clock
  EXPECT_EQ(published_.clock.back().utime % 10000, 0);
  EXPECT_EQ(published_.clock.back().period_us, 10000);
}

TEST_F(BridgeTest, FromStartTheStacksClockCountsFromTheSecondBeforeTheFirstEstimate) {
  BridgeCore bridge(BridgeParams(), kGravity, ValidationLimits(), endpoint_, BridgeOptions{false, true});
  test::ScriptedPx4 px4(bridge, bus_);
  published_ = {};
  bridge.onWallTime(0.0);
  px4.heartbeat(false, FlightMode{});
  px4.odometry(352'737'000);  // PX4 up for 352.7 s
  px4.odometry(352'741'000);
  ASSERT_EQ(published_.estimates.size(), 2u);
  EXPECT_EQ(published_.estimates[0].utime, 737'000);
  EXPECT_EQ(published_.estimates[1].utime, 741'000);
  EXPECT_EQ(published_.clock.front().utime, 730'000);
  EXPECT_EQ(bridge.health().counter("px4.clock_offset_us"), 352'000'000);
  RateCommand old = rateCommand(Vec3::Zero(), kGravity);
  old.utime = 100'000;  // on the stack's clock: 641 ms before the newest estimate
  EXPECT_EQ(bridge.onRateCommand(old), RejectReason::kStale);
  RateCommand fresh = rateCommand(Vec3::Zero(), kGravity);
  fresh.utime = 741'000;
  take(sink_);
  EXPECT_EQ(bridge.onRateCommand(fresh), RejectReason::kNone);
  EXPECT_EQ(take(sink_).setpoints.at(0).time_boot_ms, 352'741u);  // PX4's own clock on the wire
}

TEST_F(BridgeTest, BadOdometryIsCountedAndNeverReachesTheBus) {
  connect();
  published_ = {};
  mavlink::Odometry o;
  o.time_usec = static_cast<uint64_t>(utime_ + 1000);
  o.frame_id = mavlink::mav_frame::kLocalNed;
  o.child_frame_id = mavlink::mav_frame::kLocalNed;
  o.q = {1.0f, 0.0f, 0.0f, 0.0f};
  o.x = std::numeric_limits<float>::quiet_NaN();
  px4_.send(o);
  o.x = 0.0f;
  o.q = {2.0f, 0.0f, 0.0f, 0.0f};  // |q| = 2
  px4_.send(o);
  o.q = {1.0f, 0.0f, 0.0f, 0.0f};
  o.frame_id = mavlink::mav_frame::kGlobal;
  px4_.send(o);
  const uint8_t garbage[] = {0xFD, 0x05, 0x00, 0x00, 0x01, 0x01, 0x01, 0x4B, 0x01, 0x00, 1, 2, 3, 4, 5, 0, 0, 0x42};
  bridge_.onBytes(garbage, sizeof garbage, true, bus_);
  EXPECT_TRUE(published_.estimates.empty());
  EXPECT_EQ(counter("mavlink.odometry.nonfinite"), 1);
  EXPECT_EQ(counter("mavlink.odometry.quaternion"), 1);
  EXPECT_EQ(counter("mavlink.odometry.enum"), 1);
  EXPECT_EQ(counter("mavlink.drop.bad_crc"), 1);
  o.frame_id = mavlink::mav_frame::kLocalNed;
  px4_.send(o);
  EXPECT_EQ(published_.estimates.size(), 1u);
}

TEST_F(BridgeTest, OnTheBenchNothingIsArmedAskedOrSent) {
  BridgeCore bench(BridgeParams(), kGravity, ValidationLimits(), endpoint_, BridgeOptions{true, false});
  test::ScriptedPx4 px4(bench, bus_);
  bench.onWallTime(0.0);
  px4.heartbeat(false, FlightMode{});
  for (int i = 0; i < 3; ++i) px4.ack(cmd::kSetMessageInterval, mavlink::mav_result::kAccepted);
  bench.onCommand(command(CommandType::kArm));
  take(sink_);
  for (int i = 1; i <= 300; ++i) {
    utime_ += 10000;
    bench.onWallTime(0.01 * i);
    if (i % 10 == 0) px4.heartbeat(false, FlightMode{});
    px4.landed(kOnGround);
    px4.odometry(utime_);
    bench.onRateCommand(rateCommand(Vec3(0.5, 0, 0), kGravity));
  }
  const auto sent = take(sink_);
  EXPECT_TRUE(sent.setpoints.empty());
  EXPECT_TRUE(sent.commands.empty());
  EXPECT_FLOAT_EQ(bench.lastSetpoint().body_roll_rate, 0.5f);  // what it would have sent
}

}  // namespace
}  // namespace sdlqr::px4
