// The emulated PX4 (px4emu/emulator_core.hpp) against a scripted companion: it refuses OFFBOARD
// without the setpoint stream and takes it with one, acknowledges every command, streams at PX4's
// onboard rates or the rates asked, and leaves OFFBOARD after COM_OF_LOSS_T without setpoints.

#include <gtest/gtest.h>

#include <map>

#include "sdlqr/mavlink/dispatch.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/params/vehicle_file.hpp"
#include "sdlqr/px4/px4_modes.hpp"
#include "sdlqr/px4emu/emulator_core.hpp"

namespace sdlqr::px4emu {
namespace {

namespace cmd = mavlink::mav_cmd;

struct Frames : px4::ByteSink {
  bool write(const uint8_t* data, size_t size) override {
    parser.feed(data, size, 0, [&](const mavlink::Frame& f) {
      ++count[f.id];
      mavlink::dispatch(f, [&](const auto& m) {
        using M = std::decay_t<decltype(m)>;
        if constexpr (std::is_same_v<M, mavlink::CommandAck>) acks.push_back(m);
        if constexpr (std::is_same_v<M, mavlink::Heartbeat>) heartbeat = m;
      });
    });
    return true;
  }
  mavlink::Parser parser;
  std::map<uint32_t, int> count;
  std::vector<mavlink::CommandAck> acks;
  mavlink::Heartbeat heartbeat;
};

class EmulatorTest : public ::testing::Test {
 protected:
  EmulatorTest() : end_({1, 1}, frames_, [] { return uint64_t{0}; }), emulator_(config(), {}, end_) {}

  static EmulatorConfig config() {
    const params::VehicleFile f;
    return EmulatorConfig{f.vehicle, f.sim, f.estimator, f.lowlevel, f.lqr, f.faults, f.validation, f.px4_emulator};
  }
  template <class Message>
  void send(const Message& m) {
    uint8_t buffer[mavlink::kMaxFrameSize];
    const size_t size = companion_.write(m, 0, buffer);
    emulator_.onBytes(buffer, size, true);
  }
  void steps(double seconds, double setpoint_hz = 0.0, float thrust = 0.0f) {
    const int n = static_cast<int>(seconds * 1000 + 0.5);
    for (int i = 0; i < n; ++i) {
      emulator_.step(bus_);
      if (setpoint_hz > 0 && i % static_cast<int>(1000 / setpoint_hz) == 0) send(setpoint(thrust));
    }
  }
  static mavlink::SetAttitudeTarget setpoint(float thrust) {
    mavlink::SetAttitudeTarget s;
    s.target_system = 1;
    s.target_component = 1;
    s.type_mask = mavlink::attitude_target_typemask::kAttitudeIgnore;
    s.q = {1, 0, 0, 0};
    s.thrust = thrust;
    return s;
  }
  uint8_t command(uint16_t id, float p1, float p2 = 0, float p3 = 0) {
    mavlink::CommandLong c;
    c.target_system = 1;
    c.target_component = 1;
    c.command = id;
    c.param1 = p1;
    c.param2 = p2;
    c.param3 = p3;
    frames_.acks.clear();
    send(c);
    EXPECT_EQ(frames_.acks.size(), 1u);
    return frames_.acks.empty() ? 255 : frames_.acks.back().result;
  }
  uint8_t askOffboard() { return command(cmd::kDoSetMode, 1.0f, 6.0f); }

  Frames frames_;
  px4::MavlinkEndpoint end_;
  EmulatorCore emulator_;
  OutboxTo<NoObserver> bus_{NoObserver{}};
  mavlink::FrameWriter companion_{mavlink::Address{1, 191}};
};

TEST_F(EmulatorTest, RefusesOffboardWithoutTheSetpointStreamAndTakesItWithOne) {
  steps(2.0);  // the estimator initialises on VIO
  EXPECT_EQ(askOffboard(), mavlink::mav_result::kTemporarilyRejected);
  EXPECT_FALSE(emulator_.commander().mode().offboard());
  steps(1.2, 20.0);
  EXPECT_EQ(askOffboard(), mavlink::mav_result::kAccepted);
  steps(1.0, 20.0);
  EXPECT_EQ(frames_.heartbeat.custom_mode, 393216u);  // PX4's OFFBOARD: main mode 6 << 16
  EXPECT_EQ(frames_.heartbeat.autopilot, mavlink::mav_autopilot::kPx4);
  EXPECT_EQ(emulator_.health().counter("px4emu.offboard.refused"), 1);
  EXPECT_EQ(emulator_.health().counter("px4emu.offboard.entered"), 1);
}

TEST_F(EmulatorTest, AcknowledgesEveryCommandAndArmsOnlyWithTheSignal) {
  steps(2.0);
  EXPECT_EQ(command(cmd::kComponentArmDisarm, 1.0f), mavlink::mav_result::kAccepted);  // Position mode
  EXPECT_EQ(command(cmd::kComponentArmDisarm, 0.0f), mavlink::mav_result::kAccepted);
  steps(0.5, 20.0);
  ASSERT_EQ(askOffboard(), mavlink::mav_result::kAccepted);
  steps(1.5);  // the setpoints stop: no signal
  EXPECT_EQ(command(cmd::kComponentArmDisarm, 1.0f), mavlink::mav_result::kTemporarilyRejected);
  EXPECT_EQ(command(42, 0.0f), mavlink::mav_result::kUnsupported);
  EXPECT_EQ(command(cmd::kSetMessageInterval, 999.0f, 1000.0f), mavlink::mav_result::kDenied);
}

TEST_F(EmulatorTest, StreamsAtPx4sOnboardRatesOrAsAsked) {
  steps(2.0);
  frames_.count.clear();
  steps(2.0);
  EXPECT_EQ(frames_.count[mavlink::Heartbeat::kId], 2);
  EXPECT_NEAR(frames_.count[mavlink::Odometry::kId], 60, 1);
  EXPECT_NEAR(frames_.count[mavlink::HighresImu::kId], 100, 1);
  EXPECT_NEAR(frames_.count[mavlink::ExtendedSysState::kId], 10, 1);
  EXPECT_NEAR(frames_.count[mavlink::LocalPositionNed::kId], 60, 1);
  EXPECT_EQ(command(cmd::kSetMessageInterval, static_cast<float>(mavlink::Odometry::kId), 4000.0f),
            mavlink::mav_result::kAccepted);
  EXPECT_EQ(command(cmd::kSetMessageInterval, static_cast<float>(mavlink::LocalPositionNed::kId), -1.0f),
            mavlink::mav_result::kAccepted);
  frames_.count.clear();
  steps(2.0);
  EXPECT_NEAR(frames_.count[mavlink::Odometry::kId], 500, 1);  // 250 Hz: every estimate
  EXPECT_EQ(frames_.count[mavlink::LocalPositionNed::kId], 0);
}

TEST_F(EmulatorTest, LeavesOffboardAfterComOfLossTWithoutSetpoints) {
  steps(2.0, 20.0);
  ASSERT_EQ(askOffboard(), mavlink::mav_result::kAccepted);
  ASSERT_EQ(command(cmd::kComponentArmDisarm, 1.0f), mavlink::mav_result::kAccepted);
  // Hover thrust: on the ground with less, the land detector would disarm within its landed_time.
  steps(0.5, 20.0, static_cast<float>(emulator_.hoverThrottle()));
  ASSERT_TRUE(emulator_.commander().mode().offboard());
  steps(0.95);  // the last setpoint 0.95 s + at most 50 ms ago: still within COM_OF_LOSS_T = 1 s
  EXPECT_TRUE(emulator_.commander().mode().offboard());
  steps(0.1);
  EXPECT_EQ(emulator_.commander().mode(), px4::kLandMode);  // COM_OBL_RC_ACT = 4
  EXPECT_EQ(emulator_.health().counter("px4emu.offboard.lost"), 1);
}

TEST_F(EmulatorTest, SetpointsForAnotherSystemOrWithoutRatesAreIgnored) {
  steps(0.1);
  mavlink::SetAttitudeTarget other = setpoint(0.5f);
  other.target_system = 7;
  send(other);
  mavlink::SetAttitudeTarget attitude = setpoint(0.5f);
  attitude.type_mask = mavlink::attitude_target_typemask::kBodyRollRateIgnore;
  send(attitude);
  EXPECT_EQ(emulator_.health().counter("px4emu.setpoints.ignored"), 2);
  EXPECT_EQ(emulator_.health().counter("px4emu.setpoints"), 0);
  EXPECT_FALSE(emulator_.commander().offboardSignal(emulator_.utime()));
}

TEST_F(EmulatorTest, HoverThrottleIsTheAirframesWeightOverFullThrust) {
  EXPECT_NEAR(emulator_.hoverThrottle(), 0.255 * 9.81 / 5.0, 1e-9);
  EXPECT_NEAR(emulator_.hoverThrottle(), px4::ThrustMap().hover_throttle, 1e-4);  // the bridge's default
}

}  // namespace
}  // namespace sdlqr::px4emu

namespace sdlqr::px4emu {
namespace {

TEST(LandDetector, LandsOnSustainedEvidenceOnlyAndTakesOffQuicker) {
  LandDetector d;
  EXPECT_TRUE(d.landed());  // starts on the ground
  for (int i = 0; i < 199; ++i) EXPECT_TRUE(d.update(false, 0.001));
  EXPECT_FALSE(d.update(false, 0.001));  // airborne after 0.2 s without ground evidence
  // The hover-to-descent step looks like rest for a moment: 0.3 s of it is not a landing.
  for (int i = 0; i < 300; ++i) EXPECT_FALSE(d.update(true, 0.001));
  EXPECT_FALSE(d.update(false, 0.001));
  for (int i = 0; i < 499; ++i) EXPECT_FALSE(d.update(true, 0.001));
  EXPECT_TRUE(d.update(true, 0.001));  // 0.5 s of it is
}

}  // namespace
}  // namespace sdlqr::px4emu
