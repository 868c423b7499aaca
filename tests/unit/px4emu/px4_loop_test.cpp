// The px4-emulated stack in one process (px4_loop.hpp): the paper's controller flies the emulated
// PX4 through MAVLink bytes — handshake, take-off, a jump, landing and disarm; a killed controller
// hands the vehicle to PX4's offboard-loss failsafe, which lands it; a link cut while flying is the
// stack's failsafe and PX4's Hold, then OFFBOARD again; the hover throttle fits back from the log.

#include <gtest/gtest.h>

#include "px4_loop.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/px4/hover_identification.hpp"

namespace sdlqr::px4emu::test {
namespace {

mission::Scenario hoverScenario() {
  return mission::Scenario::load(std::string(SDLQR_SOURCE_DIR) + "/tests/integration/replay/hover_short.yaml");
}

const SimTruth& truthAt(const logger::FlightLog& log, double t) {
  const auto i = log.sim_truth.indexAtOrBefore(static_cast<int64_t>(t * 1e6));
  return log.sim_truth[static_cast<size_t>(std::max<std::ptrdiff_t>(0, i))];
}

TEST(Px4Loop, TheControllerFliesTheEmulatedPx4ThroughMavlink) {
  mission::Scenario scenario = hoverScenario();
  scenario.duration = 16.0;  // touchdown at 13.4 s, landed 0.5 s later (land_detector.hpp), then disarmed
  Px4Loop loop(params::VehicleFile(), scenario);
  int on_ground_in_the_air = 0;  // EXTENDED_SYS_STATE must never say ON_GROUND above the ground
  while (loop.step()) {
    const bool reported = loop.emulator().landedState() == mavlink::mav_landed_state::kOnGround;
    on_ground_in_the_air += reported && loop.emulator().sim().simulator().truth().position.z() > 0.1 ? 1 : 0;
  }
  EXPECT_EQ(on_ground_in_the_air, 0);
  const logger::FlightLog& log = loop.log();
  // Armed in OFFBOARD right after ARM (0.5 s): the zero-thrust stream ran since the link came up.
  EXPECT_EQ(loop.emulator().health().counter("px4emu.offboard.entered"), 1);
  EXPECT_EQ(loop.emulator().health().counter("px4emu.offboard.refused"), 0);
  EXPECT_EQ(loop.emulator().health().counter("px4emu.offboard.lost"), 0);
  EXPECT_NEAR(truthAt(log, 5.5).position[2], 1.0, 0.05);   // took off to 1 m
  EXPECT_NEAR(truthAt(log, 10.5).position[0], 0.5, 0.05);  // jumped 0.5 m in x
  EXPECT_LT(truthAt(log, 14.0).position[2], 0.05);         // landed
  EXPECT_FALSE(loop.emulator().commander().armed());       // and disarmed
  EXPECT_EQ(loop.bridge().intent(), px4::FlightIntent::kIdle);
  EXPECT_GT(log.state_estimate.size(), 14 * 240u);         // ODOMETRY asked at 250 Hz
  EXPECT_EQ(loop.bridge().health().counter("failsafe.no_odometry"), 0);
  EXPECT_FALSE(loop.emulator().sim().simulator().crashed());
}

TEST(Px4Loop, AKilledControllerHandsTheVehicleToPx4WhichLandsIt) {
  LoopOptions options;
  options.controller_dies_at_s = 4.0;
  mission::Scenario scenario = hoverScenario();
  Px4Loop loop(params::VehicleFile(), scenario, options);
  while (loop.seconds() < 4.9) loop.step();
  EXPECT_TRUE(loop.emulator().commander().mode().offboard());  // COM_OF_LOSS_T = 1 s not yet over
  while (loop.seconds() < 5.2) loop.step();
  EXPECT_EQ(loop.emulator().commander().mode(), px4::kLandMode);
  loop.run();
  EXPECT_EQ(loop.emulator().health().counter("px4emu.offboard.lost"), 1);
  EXPECT_EQ(loop.bridge().health().counter("failsafe.controller_silent"), 1);
  EXPECT_EQ(loop.bridge().health().counter("px4.offboard.left_by_autopilot"), 1);
  EXPECT_FALSE(loop.emulator().commander().armed());  // landed and disarmed by PX4's land detector
  EXPECT_LT(truthAt(loop.log(), 14.0).position[2], 0.05);
  EXPECT_FALSE(loop.emulator().sim().simulator().crashed());
}

TEST(Px4Loop, ALinkCutIsTheStacksFailsafeThenPx4HoldsAndOffboardResumes) {
  params::VehicleFile config;
  config.px4_emulator.com_obl_rc_act = kHoldAction;
  config.px4_emulator.com_of_loss_t = 0.5;
  LoopOptions options;
  options.link_down_at_s = 4.0;
  options.link_down_for_s = 1.0;
  Px4Loop loop(config, hoverScenario(), options);
  while (loop.seconds() < 4.8) loop.step();
  EXPECT_EQ(loop.emulator().commander().mode(), px4::kHoldMode);
  EXPECT_EQ(loop.bridge().state(), px4::BridgeState::kLinkLost);
  loop.run();
  EXPECT_EQ(loop.bridge().health().counter("px4.offboard.left_in_link_loss"), 1);
  EXPECT_EQ(loop.emulator().health().counter("px4emu.offboard.entered"), 2);  // taken again
  EXPECT_NEAR(truthAt(loop.log(), 10.5).position[0], 0.5, 0.05);  // the jump at 6 s flown
  EXPECT_LT(truthAt(loop.log(), 14.0).position[2], 0.05);
  double lowest_in_outage = 10.0;
  for (double t = 4.0; t < 6.0; t += 0.01) lowest_in_outage = std::min(lowest_in_outage, truthAt(loop.log(), t).position[2]);
  EXPECT_GT(lowest_in_outage, 0.8);  // held, not dropped
}

TEST(Px4Loop, TheHoverThrottleFitsBackFromTheFlight) {
  params::VehicleFile config;
  config.px4.thrust.hover_throttle = 0.45;  // a wrong guess: the vehicle needs 0.5003
  Px4Loop loop(config, hoverScenario());
  loop.run();
  const auto samples = px4::hoverSamples(loop.log(), config.px4.thrust, config.lqr.gravity);
  const px4::HoverFit fit = px4::fitHoverThrottle(samples, 0.0, config.lqr.gravity);
  EXPECT_TRUE(fit.error.empty()) << fit.error;
  EXPECT_NEAR(fit.hover_throttle, loop.emulator().hoverThrottle(), 0.01);
}

}  // namespace
}  // namespace sdlqr::px4emu::test
