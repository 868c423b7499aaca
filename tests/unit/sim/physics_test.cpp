// Rigid body, rotors, motor lag, rotor drag and disturbances against closed-form motion.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "sdlqr/math/model.hpp"
#include "sdlqr/sim/rotors.hpp"
#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

using namespace test;  // sim_test_support.hpp

TEST(Physics, FreeFallWithMotorsOffMatchesHalfGTSquared) {
  // GIVEN a vehicle released at rest 100 m up with the motors off
  SimParams p = idealParams();
  p.initial_position = Vec3(1.0, 2.0, 100.0);
  Simulator sim(VehicleParams(), p);
  ASSERT_FALSE(sim.onGround());
  // WHEN it falls for 3 s
  runFor(sim, 3.0);
  // THEN z = z0 - g t^2 / 2 and v = -g t, with no horizontal motion (no rotor drag when stopped)
  const double t = sim.utime() * 1e-6;
  EXPECT_DOUBLE_EQ(t, 3.0);
  const double expected_z = 100.0 - 0.5 * p.gravity * t * t;
  std::cout << "free fall z after 3 s: " << sim.body().position.z() << " (expected " << expected_z << ")\n";
  EXPECT_NEAR(sim.body().position.z(), expected_z, 1e-9);
  EXPECT_NEAR(sim.body().velocity.z(), -p.gravity * t, 1e-9);
  EXPECT_DOUBLE_EQ(sim.body().position.x(), 1.0);
  EXPECT_DOUBLE_EQ(sim.body().position.y(), 2.0);
  EXPECT_NEAR(sim.acceleration().z(), -p.gravity, 1e-9);
}

TEST(Physics, HoverThrustHoldsAltitude) {
  // GIVEN a vehicle in the air whose motors already produce m g / 4 each
  const VehicleParams v;
  Simulator sim(v, idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 2.0)), hoverThrust(v));
  // WHEN hover thrust is commanded for 10 s
  sim.setMotorCommand(armed(hoverThrust(v)));
  runFor(sim, 10.0);
  // THEN the vehicle does not move
  EXPECT_NEAR(sim.body().position.z(), 2.0, 1e-9);
  EXPECT_LT(sim.body().velocity.norm(), 1e-9);
  EXPECT_LT(sim.body().body_rate.norm(), 1e-12);
}

TEST(Physics, HoverThrustHoldsAltitudeOnceMotorLagSettles) {
  // GIVEN a vehicle dropped in the air with the motors stopped (no rotor drag: it would brake
  // the vertical speed this test measures)
  VehicleParams v;
  v.rotor_drag.setZero();
  Simulator sim(v, idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 5.0)));
  // WHEN hover thrust is commanded
  sim.setMotorCommand(armed(hoverThrust(v)));
  runFor(sim, 10 * v.motor_time_constant);
  const double v_settled = sim.body().velocity.z();
  runFor(sim, 1.0);
  // THEN the thrust deficit while the motors spin up costs exactly g tau of vertical speed,
  // after which the vertical speed stays constant (no acceleration at hover thrust)
  const double g = kDefaultGravity;
  std::cout << "speed lost to motor lag: " << -v_settled << " m/s (g tau = " << g * v.motor_time_constant << ")\n";
  EXPECT_NEAR(v_settled, -g * v.motor_time_constant, 1e-3 * g * v.motor_time_constant);
  EXPECT_NEAR(sim.body().velocity.z(), v_settled, 1e-4);
  EXPECT_NEAR(sim.acceleration().z(), 0.0, 1e-6);
}

double measuredTimeConstant(double tau) {
  VehicleParams v;
  v.motor_time_constant = tau;
  Simulator sim(v, idealParams());  // on the ground: the motor lag runs all the same
  const double step_thrust = 1.0;
  sim.setMotorCommand(armed(Vec4::Constant(step_thrust)));
  double previous = 0.0;
  for (int i = 0; i < 1000; ++i) {
    const double t_before = sim.utime() * 1e-6;
    sim.step();
    const double now = sim.rotorThrust()[0];
    const double target = (1.0 - std::exp(-1.0)) * step_thrust;
    if (now >= target) {
      // Linear interpolation inside the step where the response crosses 63.2 %.
      return t_before + sim.period() * (target - previous) / (now - previous);
    }
    previous = now;
  }
  return -1.0;
}

TEST(Physics, MotorLagTimeConstantMeasuredFromAStep) {
  for (const double tau : {0.02, 0.03, 0.04}) {
    const double measured = measuredTimeConstant(tau);
    std::cout << "motor time constant " << tau << " s, measured from a step: " << measured << " s\n";
    EXPECT_NEAR(measured, tau, 2e-5);
  }
}

TEST(Physics, RollTorqueFromRotorsGivesTorqueOverInertia) {
  // GIVEN a hovering vehicle whose rotors add a pure roll torque
  const VehicleParams v;
  const double g = kDefaultGravity;
  const double roll_torque = 0.01;  // [N m]
  const Vec4 thrust = thrustFor(v, v.mass * g, Vec3(roll_torque, 0.0, 0.0));
  Simulator sim(v, idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 10.0)), thrust);
  sim.setMotorCommand(armed(thrust));
  // WHEN it runs 50 ms
  runFor(sim, 0.05);
  // THEN omega_x grows at tau / Jxx and nothing else turns
  const double expected = roll_torque / v.inertia_diag.x() * 0.05;
  std::cout << "roll rate after 50 ms: " << sim.body().body_rate.x() << " rad/s (expected " << expected << ")\n";
  EXPECT_NEAR(sim.body().body_rate.x(), expected, 1e-9);
  EXPECT_NEAR(sim.body().body_rate.y(), 0.0, 1e-12);
  EXPECT_NEAR(sim.body().body_rate.z(), 0.0, 1e-12);
}

TEST(Physics, PitchTorqueDisturbanceGivesTorqueOverInertia) {
  const VehicleParams v;
  Simulator sim(v, idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 10.0)));
  Disturbance d;
  d.torque = Vec3(0.0, -0.004, 0.0);
  d.duration = 1.0;
  ASSERT_EQ(sim.addDisturbance(d), RejectReason::kNone);
  runFor(sim, 0.1);
  EXPECT_NEAR(sim.body().body_rate.y(), -0.004 / v.inertia_diag.y() * 0.1, 1e-9);
}

TEST(Physics, YawTorqueSignFollowsEffectiveness) {
  // GIVEN rotor thrusts that effectiveness() maps to a positive yaw torque at hover
  const VehicleParams v;
  const double yaw_torque = 0.002;
  const Vec4 thrust = thrustFor(v, v.mass * kDefaultGravity, Vec3(0.0, 0.0, yaw_torque));
  // The rotors spinning with yaw_sign +1 must be the ones sped up.
  for (int i = 0; i < 4; ++i) EXPECT_EQ(thrust[i] > hoverThrust(v)[i], v.yaw_sign[i] > 0) << "rotor " << i;
  Simulator sim(v, idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 10.0)), thrust);
  sim.setMotorCommand(armed(thrust));
  runFor(sim, 0.2);
  // THEN the body turns about +z at tau_z / Jzz
  EXPECT_NEAR(sim.body().body_rate.z(), yaw_torque / v.inertia_diag.z() * 0.2, 1e-9);
  EXPECT_GT(quat::yaw(sim.body().orientation), 0.0);
}

TEST(Physics, SaturationClampsEachRotor) {
  VehicleParams v;
  v.min_rotor_thrust = 0.1;
  Simulator sim(v, idealParams());
  // Above max on rotor 0, below min on rotor 1, within range on rotors 2 and 3.
  ASSERT_EQ(sim.setMotorCommand(armed(Vec4(2.0, 0.0, 0.5, 0.9))), RejectReason::kNone);
  runFor(sim, 0.5);
  const Vec4 thrust = sim.rotorThrust();
  EXPECT_NEAR(thrust[0], v.max_rotor_thrust, 1e-6);
  EXPECT_NEAR(thrust[1], v.min_rotor_thrust, 1e-6);
  EXPECT_NEAR(thrust[2], 0.5, 1e-6);
  EXPECT_NEAR(thrust[3], 0.9, 1e-6);
  // Disarmed means zero thrust whatever the setpoints say.
  MotorCommand off = armed(Vec4::Constant(1.0));
  off.armed = false;
  sim.setMotorCommand(off);
  runFor(sim, 0.5);
  EXPECT_LT(sim.rotorThrust().maxCoeff(), 1e-6);
}

TEST(Physics, RotorDragDeceleratesAtTheConfiguredRate) {
  // GIVEN a level vehicle at hover thrust moving horizontally
  const VehicleParams v;  // rotor_drag 0.30, 0.30 1/s in x, y
  Simulator sim(v, idealParams());
  sim.setBodyState(airborne(Vec3(0, 0, 10.0), Vec3(2.0, -1.0, 0.0), quat::fromYaw(0.7)), hoverThrust(v));
  sim.setMotorCommand(armed(hoverThrust(v)));
  // WHEN it coasts for 2 s
  runFor(sim, 2.0);
  // THEN v(t) = v0 exp(-d t) on each body axis (here x and y share d, so any yaw works)
  const double decay = std::exp(-v.rotor_drag.x() * 2.0);
  std::cout << "velocity after 2 s of rotor drag: " << sim.body().velocity.transpose() << " (expected "
            << 2.0 * decay << ", " << -1.0 * decay << ")\n";
  EXPECT_NEAR(sim.body().velocity.x(), 2.0 * decay, 1e-8);
  EXPECT_NEAR(sim.body().velocity.y(), -1.0 * decay, 1e-8);
  EXPECT_NEAR(sim.body().position.z(), 10.0, 1e-9);
}

// The controllers' model of the drag (math/model.hpp rotorDragAcceleration, lqr.model_rotor_drag) is
// the plant's: at equal rotor thrusts the wrench's force per mass is c z_b plus exactly that term.
TEST(Physics, TheModelsRotorDragIsThePlants) {
  VehicleParams v;
  v.rotor_drag = Vec3(0.69, 0.69, 1.34);
  const RotorWrench wrench(v, 9.81);
  RotorDrag model;
  model.coefficients = v.rotor_drag;
  model.gravity = 9.81;
  for (double c : {3.0, 9.81, 25.0}) {
    BodyState s;
    s.orientation = quat::exp(Vec3(0.4, -0.3, 1.1));
    s.velocity = Vec3(6.0, -3.0, 2.0);
    const Wrench w = wrench(Vec4::Constant(v.mass * c / 4.0), s);
    const Vec3 expected = c * quat::bodyZ(s.orientation) + rotorDragAcceleration(s.orientation, s.velocity, c, model);
    EXPECT_LT((w.force_world / v.mass - expected).norm(), 1e-12) << "c " << c;
  }
}

TEST(Physics, DisturbanceForceMovesTheVehicleForItsDurationOnly) {
  // GIVEN a falling vehicle (motors off: no rotor drag) pulled sideways from 0.1 s to 0.4 s
  const VehicleParams v;
  SimParams p = idealParams();
  p.initial_position = Vec3(0, 0, 100.0);
  Simulator sim(v, p);
  Disturbance pull;
  pull.start_utime = 100000;
  pull.duration = 0.3;
  pull.force = Vec3(0.51, 0.0, 0.0);
  ASSERT_EQ(sim.addDisturbance(pull), RejectReason::kNone);
  const double a = pull.force.x() / v.mass;  // 2 m/s^2
  // WHEN time passes
  runFor(sim, 0.1);
  EXPECT_DOUBLE_EQ(sim.body().velocity.x(), 0.0);
  runFor(sim, 0.15);
  EXPECT_NEAR(sim.body().velocity.x(), a * 0.15, 1e-12);
  EXPECT_NEAR(sim.truth().external_force.x(), 0.51, 1e-12);
  runFor(sim, 0.15);
  // THEN it gained F/m x duration and then keeps that speed
  EXPECT_NEAR(sim.body().velocity.x(), a * 0.3, 1e-12);
  runFor(sim, 0.6);
  EXPECT_NEAR(sim.body().velocity.x(), a * 0.3, 1e-12);
  EXPECT_NEAR(sim.body().position.x(), 0.5 * a * 0.09 + a * 0.3 * 0.6, 1e-9);
  EXPECT_EQ(sim.truth().external_force.norm(), 0.0);
}

TEST(Physics, HoldDisturbanceSettlesWhereTheSpringCarriesTheWeight) {
  // GIVEN a vehicle with motors off held by a spring-damper at its start point
  const VehicleParams v;
  SimParams p = idealParams();
  p.initial_position = Vec3(0, 0, 3.0);
  Simulator sim(v, p);
  Disturbance hold;
  hold.mode = DisturbanceMode::kHold;
  hold.duration = 30.0;
  hold.hold_position = Vec3(0, 0, 3.0);
  hold.hold_stiffness = 50.0;
  hold.hold_damping = 5.0;
  ASSERT_EQ(sim.addDisturbance(hold), RejectReason::kNone);
  runFor(sim, 10.0);
  // THEN it hangs m g / k below the anchor, at rest
  const double sag = v.mass * kDefaultGravity / hold.hold_stiffness;
  EXPECT_NEAR(sim.body().position.z(), 3.0 - sag, 1e-6);
  EXPECT_LT(sim.body().velocity.norm(), 1e-6);
}

}  // namespace
}  // namespace sdlqr::sim
