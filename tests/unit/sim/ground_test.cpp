// Ground contact: starts landed, rests exactly, lifts off at the weight, never tunnels, flags crashes.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

using namespace test;  // sim_test_support.hpp

TEST(Ground, StartsLandedAndRestsWithoutJitterBelowWeight) {
  // GIVEN the default start (landed at z = 0) with the battery model on
  const VehicleParams v;
  Simulator sim(v, SimParams());
  EXPECT_TRUE(sim.onGround());
  EXPECT_TRUE(sim.truth().on_ground);
  // WHEN the motors push 90 % of the weight for 3 s
  sim.setMotorCommand(armed(0.9 * hoverThrust(v)));
  for (int64_t i = stepsFor(sim, 3.0); i > 0; --i) {
    sim.step();
    // THEN it stays exactly on the ground, motionless, every single step
    ASSERT_EQ(sim.body().position.z(), 0.0) << "at t=" << sim.utime();
    ASSERT_EQ(sim.body().velocity.norm(), 0.0);
    ASSERT_EQ(sim.body().body_rate.norm(), 0.0);
    ASSERT_EQ(sim.acceleration().norm(), 0.0);
    ASSERT_TRUE(sim.onGround());
  }
  EXPECT_FALSE(sim.crashed());
}

TEST(Ground, TakesOffWhenThrustExceedsWeight) {
  const VehicleParams v;
  Simulator sim(v, idealParams());
  const double weight = v.mass * kDefaultGravity;
  sim.setMotorCommand(armed(1.2 * hoverThrust(v)));
  // Thrust sum at the start of the step before lift-off and at the end of the lift-off step.
  double thrust_one_step_earlier = -1.0;
  double thrust_after_liftoff = -1.0;
  double previous_start = 0.0;
  for (int64_t i = stepsFor(sim, 1.0); i > 0; --i) {
    const double start = sim.rotorThrust().sum();
    sim.step();
    ASSERT_GE(sim.body().position.z(), 0.0);
    if (!sim.onGround() && thrust_after_liftoff < 0.0) {
      thrust_one_step_earlier = previous_start;
      thrust_after_liftoff = sim.rotorThrust().sum();
    }
    previous_start = start;
  }
  // The vehicle leaves within one step of the rising thrust passing the weight.
  std::cout << "lift-off: thrust " << thrust_one_step_earlier << " N one step before, " << thrust_after_liftoff
            << " N after; weight " << weight << " N\n";
  EXPECT_LE(thrust_one_step_earlier, weight);
  EXPECT_GT(thrust_after_liftoff, weight);
  EXPECT_FALSE(sim.onGround());
  EXPECT_GT(sim.body().position.z(), 0.5);  // 0.2 g upwards for ~0.9 s is ~0.8 m
  EXPECT_FALSE(sim.crashed());
}

TEST(Ground, ExternalUpwardForceLiftsAGroundedVehicle) {
  const VehicleParams v;
  Simulator sim(v, idealParams());
  Disturbance lift;
  lift.force = Vec3(0, 0, 1.5 * v.mass * kDefaultGravity);
  lift.duration = 0.2;
  ASSERT_EQ(sim.addDisturbance(lift), RejectReason::kNone);
  sim.step();
  EXPECT_FALSE(sim.onGround());
  EXPECT_GT(sim.body().position.z(), 0.0);
}

TEST(Ground, FastImpactNeverTunnelsAndIsACrash) {
  // GIVEN a vehicle 1 m up diving at 30 m/s (3 cm per physics step)
  Simulator sim(VehicleParams(), idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 1.0), Vec3(0, 0, -30.0)));
  for (int64_t i = stepsFor(sim, 0.5); i > 0; --i) {
    sim.step();
    ASSERT_GE(sim.body().position.z(), 0.0) << "sank below the ground at t=" << sim.utime();
  }
  EXPECT_TRUE(sim.onGround());
  EXPECT_TRUE(sim.crashed());
  EXPECT_TRUE(sim.truth().crashed);
  EXPECT_EQ(sim.body().velocity.norm(), 0.0);
}

TEST(Ground, HardLandingIsACrashAndSoftLandingIsNot) {
  const double crash_speed = SimParams().ground.crash_speed;
  // Drop heights giving touchdown speeds of 1.5 x and 0.5 x the crash speed.
  for (const double factor : {1.5, 0.5}) {
    const double drop = std::pow(factor * crash_speed, 2) / (2.0 * kDefaultGravity);
    SimParams p = idealParams();
    p.initial_position = Vec3(0, 0, drop);
    Simulator sim(VehicleParams(), p);
    runFor(sim, 2.0);
    EXPECT_TRUE(sim.onGround());
    EXPECT_EQ(sim.crashed(), factor > 1.0) << "drop " << drop << " m";
    EXPECT_EQ(sim.body().position.z(), 0.0);
  }
}

TEST(Ground, UpsideDownTouchdownIsACrashAndSlightTiltIsNot) {
  for (const double tilt : {2.5, 0.3}) {
    Simulator sim(VehicleParams(), idealParams());
    sim.setBodyState(airborne(Vec3(0, 0, 0.02), Vec3::Zero(), quat::exp(Vec3(tilt, 0.0, 0.0))));
    runFor(sim, 0.5);
    EXPECT_TRUE(sim.onGround());
    EXPECT_EQ(sim.crashed(), tilt > SimParams().ground.crash_tilt) << "tilt " << tilt;
    // Once down it stands level on its legs.
    EXPECT_NEAR(quat::tilt(sim.body().orientation), 0.0, 1e-12);
  }
}

TEST(Ground, KeepsPositionAndYawWhereItLanded) {
  Simulator sim(VehicleParams(), idealParams());
  const Quat yawed = quat::fromYaw(1.2);
  sim.setBodyState(airborne(Vec3(3.0, -2.0, 0.05), Vec3(0.0, 0.0, -0.5), yawed));
  runFor(sim, 1.0);
  ASSERT_TRUE(sim.onGround());
  EXPECT_NEAR(sim.body().position.x(), 3.0, 1e-12);
  EXPECT_NEAR(sim.body().position.y(), -2.0, 1e-12);
  EXPECT_NEAR(quat::yaw(sim.body().orientation), 1.2, 1e-12);
  EXPECT_FALSE(sim.crashed());
}

}  // namespace
}  // namespace sdlqr::sim
