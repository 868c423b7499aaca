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
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, 0.5, 0.5, 0.5)), v), MotorCommandFault::kNone);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, kNaN, 0.5, 0.5)), v), MotorCommandFault::kNonFinite);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, 0.5, HUGE_VAL, 0.5)), v), MotorCommandFault::kNonFinite);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(-0.01, 0.5, 0.5, 0.5)), v), MotorCommandFault::kThrustRange);
  EXPECT_EQ(checkMotorCommand(armed(Vec4(0.5, 0.5, 0.5, 2.0 * v.max_rotor_thrust + 1e-9)), v),
            MotorCommandFault::kThrustRange);
  EXPECT_EQ(checkMotorCommand(armed(Vec4::Constant(2.0 * v.max_rotor_thrust)), v), MotorCommandFault::kNone);
  MotorCommand bad_mode = armed(Vec4::Zero());
  bad_mode.mode = static_cast<MotorMode>(9);
  EXPECT_EQ(checkMotorCommand(bad_mode, v), MotorCommandFault::kMode);
}

TEST(InputChecks, RejectedMotorCommandLeavesTheLastGoodOneInForce) {
  const VehicleParams v;
  Simulator sim(v, test::idealParams());
  ASSERT_EQ(sim.setMotorCommand(armed(Vec4::Constant(0.4))), MotorCommandFault::kNone);
  EXPECT_EQ(sim.setMotorCommand(armed(Vec4::Constant(kNaN))), MotorCommandFault::kNonFinite);
  test::runFor(sim, 0.5);
  EXPECT_NEAR(sim.rotorThrust()[0], 0.4, 1e-6);
  EXPECT_TRUE(sim.rotorThrust().allFinite());
}

TEST(InputChecks, DisturbanceFaults) {
  const DisturbanceLimits limits;
  Disturbance ok;
  ok.duration = 1.0;
  ok.force = Vec3(1.0, 0.0, 0.0);
  EXPECT_EQ(checkDisturbance(ok, limits), DisturbanceFault::kNone);

  Disturbance d = ok;
  d.torque.y() = kNaN;
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kNonFinite);
  d = ok;
  d.duration = -0.1;
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kDuration);
  d.duration = limits.max_duration * 2.0;
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kDuration);
  d = ok;
  d.force = Vec3(30.0, 30.0, 30.0);  // 52 N
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kForce);
  d = ok;
  d.torque = Vec3(0.0, 0.0, 1.5);
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kTorque);
  d = ok;
  d.mode = DisturbanceMode::kHold;
  d.hold_stiffness = -1.0;
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kHoldGains);
  d.hold_stiffness = 10.0;
  d.hold_damping = limits.max_damping + 1.0;
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kHoldGains);
  d = ok;
  d.mode = static_cast<DisturbanceMode>(5);
  EXPECT_EQ(checkDisturbance(d, limits), DisturbanceFault::kMode);
}

TEST(InputChecks, DisturbanceQueueIsBoundedAndFreesExpiredSlots) {
  Simulator sim(VehicleParams(), test::idealParams());
  Disturbance d;
  d.duration = 0.01;
  d.force = Vec3(0.0, 0.0, 0.1);
  for (int i = 0; i < DisturbanceSet::kCapacity; ++i) ASSERT_EQ(sim.addDisturbance(d), DisturbanceFault::kNone);
  EXPECT_EQ(sim.addDisturbance(d), DisturbanceFault::kQueueFull);
  test::runFor(sim, 0.02);  // all have ended
  sim.step();
  EXPECT_EQ(sim.addDisturbance(d), DisturbanceFault::kNone);
}

TEST(InputChecks, EveryFaultHasADistinctCounterName) {
  std::vector<std::string> names;
  for (MotorCommandFault f : kAllMotorCommandFaults) names.push_back(counterName(f));
  for (DisturbanceFault f : kAllDisturbanceFaults) names.push_back(counterName(f));
  for (size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(names[i].rfind("reject.", 0), 0u) << names[i];
    for (size_t j = i + 1; j < names.size(); ++j) EXPECT_NE(names[i], names[j]);
  }
}

}  // namespace
}  // namespace sdlqr::sim
