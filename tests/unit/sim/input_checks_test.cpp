// Malformed MOTOR_CMD and DISTURBANCE requests are refused, named, and never applied.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

using test::armed;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(InputChecks, MotorCommandFaults) {
  const VehicleParams v;
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, 0.5, 0.5, 0.5)), v), RejectReason::kNone);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, kNaN, 0.5, 0.5)), v), RejectReason::kNonFinite);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, 0.5, HUGE_VAL, 0.5)), v), RejectReason::kNonFinite);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(-0.01, 0.5, 0.5, 0.5)), v), RejectReason::kOutOfRange);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, 0.5, 0.5, 2.0 * v.max_rotor_thrust + 1e-9)), v),
            RejectReason::kOutOfRange);
  EXPECT_EQ(checkMotorCommand(armed(Vec4::Constant(2.0 * v.max_rotor_thrust)), v), RejectReason::kNone);
  MotorCommand bad_mode = armed(Vec4::Zero());
  bad_mode.mode = static_cast<MotorMode>(9);
  EXPECT_EQ(checkMotorCommand(bad_mode, v), RejectReason::kBadEnum);
}

TEST(InputChecks, RejectedMotorCommandLeavesTheLastGoodOneInForce) {
  const VehicleParams v;
  Simulator sim(v, test::idealParams());
  ASSERT_EQ(sim.setMotorCommand(armed(Vec4::Constant(0.4))), RejectReason::kNone);
  EXPECT_EQ(sim.setMotorCommand(armed(Vec4::Constant(kNaN))), RejectReason::kNonFinite);
  test::runFor(sim, 0.5);
  EXPECT_NEAR(sim.rotorThrust()[0], 0.4, 1e-6);
  EXPECT_TRUE(sim.rotorThrust().allFinite());
}

TEST(InputChecks, DisturbanceFaults) {
  const DisturbanceLimits limits;
  Disturbance ok;
  ok.duration = 1.0;
  ok.force = Vec3(1.0, 0.0, 0.0);
  EXPECT_EQ(checkDisturbance(ok, limits), RejectReason::kNone);

  Disturbance d = ok;
  d.torque.y() = kNaN;
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kNonFinite);
  d = ok;
  d.duration = -0.1;
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kOutOfRange);
  d.duration = limits.max_duration * 2.0;
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kOutOfRange);
  d = ok;
  d.force = Vec3(30.0, 30.0, 30.0);  // 52 N
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kOutOfRange);
  d = ok;
  d.torque = Vec3(0.0, 0.0, 1.5);
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kOutOfRange);
  d = ok;
  d.mode = DisturbanceMode::kHold;
  d.hold_stiffness = -1.0;
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kOutOfRange);
  d.hold_stiffness = 10.0;
  d.hold_damping = limits.max_damping + 1.0;
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kOutOfRange);
  d = ok;
  d.mode = static_cast<DisturbanceMode>(5);
  EXPECT_EQ(checkDisturbance(d, limits), RejectReason::kBadEnum);
}

TEST(InputChecks, DisturbanceQueueIsBoundedAndFreesExpiredSlots) {
  Simulator sim(VehicleParams(), test::idealParams());
  Disturbance d;
  d.duration = 0.01;
  d.force = Vec3(0.0, 0.0, 0.1);
  for (int i = 0; i < DisturbanceSet::kCapacity; ++i) ASSERT_EQ(sim.addDisturbance(d), RejectReason::kNone);
  EXPECT_EQ(sim.addDisturbance(d), RejectReason::kQueueFull);
  test::runFor(sim, 0.02);  // all have ended
  sim.step();
  EXPECT_EQ(sim.addDisturbance(d), RejectReason::kNone);
}

}  // namespace
}  // namespace sdlqr::sim
