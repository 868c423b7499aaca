// The scenario's simulated world (sim/stress_params.hpp): plant mismatch, wind, airborne start and
// throw — each checked against what physics says, and each default changing nothing.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sdlqr/config/config.hpp"
#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

using test::armed;
using test::hoverThrust;
using test::idealParams;

SimStress stressFrom(const std::string& yaml) {
  return SimStress::load(ConfigReader(YAML::Load(yaml), "sim"));
}

// At rest at 5 m, the rotors spun up to the hover thrust of the vehicle file's mass and the motors
// armed at it: whatever moves the vehicle then is the stressor's doing.
void hoverAt5m(Simulator& sim, const VehicleParams& v) {
  sim.setBodyState(test::airborne(Vec3(0, 0, 5)), hoverThrust(v));
  sim.setMotorCommand(armed(hoverThrust(v)));
}

// GIVEN hover thrust for the file's mass WHEN the true mass is 20 % more THEN the vehicle starts
// sinking at g (1 - 1/1.2), as Newton says.
TEST(PlantOverride, HeavierPlantSinksAtTheMissingThrust) {
  const VehicleParams v;
  SimStress stress = stressFrom("{plant: {mass_scale: 1.2}}");
  Simulator sim(v, idealParams(), 1, stress);
  hoverAt5m(sim, v);
  sim.step();  // from rest: no rotor drag yet
  const double expected = -kDefaultGravity * (1.0 - 1.0 / 1.2);
  EXPECT_NEAR(sim.acceleration().z(), expected, 1e-3);
}

// GIVEN hover thrust WHEN 15 % of the mass is dropped at 0.5 s THEN the vehicle hovers until then
// and climbs at g (1 / 0.85 - 1) from the first step after, as Newton says.
TEST(PayloadDrop, TheLighterPlantClimbsFromTheDropOn) {
  const VehicleParams v;
  Simulator sim(v, idealParams(), 1, stressFrom("{payload_drop: {at: 0.5, mass_scale: 0.85}}"));
  hoverAt5m(sim, v);
  while (sim.utime() < 500000) {
    sim.step();
    EXPECT_NEAR(sim.acceleration().z(), 0.0, 1e-9) << "before the drop";
  }
  sim.step();
  EXPECT_NEAR(sim.acceleration().z(), kDefaultGravity * (1.0 / 0.85 - 1.0), 1e-3);
}

TEST(PlantOverride, ThrustCoefficientScalesTheProducedThrust) {
  const VehicleParams v;
  Simulator sim(v, idealParams(), 1, stressFrom("{plant: {thrust_scale: 0.8}}"));
  hoverAt5m(sim, v);
  sim.step();
  EXPECT_NEAR(sim.rotorThrust().sum(), 0.8 * hoverThrust(v).sum(), 1e-12);
}

TEST(PlantOverride, SlowerMotorsReachTheSetpointLater) {
  const VehicleParams v;
  Simulator nominal(v, idealParams(), 1);
  Simulator slow(v, idealParams(), 1, stressFrom("{plant: {motor_time_constant_scale: 3.0}}"));
  for (Simulator* s : {&nominal, &slow}) {
    s->setBodyState(test::airborne(Vec3(0, 0, 5)));
    s->setMotorCommand(armed(hoverThrust(v)));
    for (int i = 0; i < 30; ++i) s->step();  // one nominal time constant
  }
  EXPECT_NEAR(nominal.rotorThrust()[0] / hoverThrust(v)[0], 1.0 - std::exp(-1.0), 1e-3);
  EXPECT_NEAR(slow.rotorThrust()[0] / hoverThrust(v)[0], 1.0 - std::exp(-1.0 / 3.0), 1e-3);
}

TEST(PlantOverride, DefaultsFlyBitForBitAsWithout) {
  const VehicleParams v;
  Simulator plain(v, SimParams(), 3);
  Simulator with_defaults(v, SimParams(), 3, SimStress());
  for (Simulator* s : {&plain, &with_defaults}) s->setMotorCommand(armed(1.05 * hoverThrust(v)));
  for (int i = 0; i < 2000; ++i) {
    const StepOutput a = plain.step();
    const StepOutput b = with_defaults.step();
    ASSERT_EQ(a.imu.has_value(), b.imu.has_value());
    if (a.imu) {
      ASSERT_EQ(a.imu->accel, b.imu->accel) << "step " << i;
    }
  }
  EXPECT_EQ(plain.body().position, with_defaults.body().position);
}

// Steady wind on a vehicle hovering in place: the rotor drag pushes it downwind.
TEST(Wind, SteadyWindPushesDownwind) {
  const VehicleParams v;
  Simulator sim(v, idealParams(), 1, stressFrom("{wind: {steady: [3, 0, 0]}}"));
  hoverAt5m(sim, v);
  sim.step();
  // -m D (v - w) at hover rotor speed: m 0.3 1/s 3 m/s downwind.
  EXPECT_NEAR(sim.acceleration().x(), v.rotor_drag.x() * 3.0, 1e-3);
  EXPECT_EQ(sim.windVelocity(), Vec3(3, 0, 0));
}

// The turbulence has the std it was given and the correlation of a first-order process; a seed
// repeats it, another seed does not.
TEST(Wind, GustsHaveTheirStdAndCorrelationAndFollowTheSeed) {
  WindParams p;
  p.gust_std = Vec3(1.0, 0.5, 0.0);
  p.gust_time_constant = 0.5;
  const double dt = 0.001;
  Wind a(p, dt, 7), b(p, dt, 7), c(p, dt, 8);
  std::vector<double> x;
  double sum2_y = 0.0, max_z = 0.0;
  bool differs = false;
  const int n = 400000;  // 400 s: 800 correlation times
  for (int i = 0; i < n; ++i) {
    a.advance();
    b.advance();
    c.advance();
    ASSERT_EQ(a.velocity(), b.velocity()) << "step " << i;
    differs |= a.velocity() != c.velocity();
    x.push_back(a.velocity().x());
    sum2_y += a.velocity().y() * a.velocity().y();
    max_z = std::max(max_z, std::abs(a.velocity().z()));
  }
  EXPECT_TRUE(differs);
  double sum2 = 0.0, lag = 0.0;
  const int shift = 500;  // one time constant
  for (int i = 0; i < n; ++i) sum2 += x[static_cast<size_t>(i)] * x[static_cast<size_t>(i)];
  for (int i = 0; i + shift < n; ++i) lag += x[static_cast<size_t>(i)] * x[static_cast<size_t>(i + shift)];
  EXPECT_NEAR(std::sqrt(sum2 / n), 1.0, 0.1);
  EXPECT_NEAR(std::sqrt(sum2_y / n), 0.5, 0.05);
  EXPECT_NEAR(lag / sum2, std::exp(-1.0), 0.1);
  EXPECT_EQ(max_z, 0.0);
}

TEST(Wind, FrameDragOpposesTheRelativeAir) {
  EXPECT_EQ(frameDrag(0.1, Vec3(0, 0, 0), Vec3(2, 0, 0)), Vec3(0.4, 0, 0));
  EXPECT_EQ(frameDrag(0.1, Vec3(2, 0, 0), Vec3(2, 0, 0)), Vec3::Zero());
}

TEST(AirborneStart, UpsideDownWithItsVelocityAndRates) {
  const VehicleParams v;
  Simulator sim(v, idealParams(), 1,
                stressFrom("{airborne_start: {position: [1, 2, 3], attitude_deg: [180, 0, 0], velocity: [1, 0, 0],"
                           " body_rate: [0, 0, 2], motors_spinning: false}}"));
  EXPECT_FALSE(sim.onGround());
  EXPECT_EQ(sim.body().position, Vec3(1, 2, 3));
  EXPECT_NEAR(quat::bodyZ(sim.body().orientation).z(), -1.0, 1e-12);
  EXPECT_EQ(sim.body().velocity, Vec3(1, 0, 0));
  EXPECT_EQ(sim.body().body_rate, Vec3(0, 0, 2));
  EXPECT_EQ(sim.rotorThrust(), Vec4::Zero());
  sim.step();
  EXPECT_NEAR(sim.acceleration().z(), -kDefaultGravity, 1e-9);  // free fall, motors stopped
}

TEST(AirborneStart, SpinningMotorsStartAtHoverThrust) {
  const VehicleParams v;
  Simulator sim(v, idealParams(), 1, stressFrom("{airborne_start: {position: [0, 0, 2], attitude_deg: [60, 0, 0]}}"));
  EXPECT_NEAR(sim.rotorThrust().sum(), hoverThrust(v).sum(), 1e-12);
  EXPECT_NEAR(quat::tilt(sim.body().orientation), M_PI / 3.0, 1e-12);
}

// GIVEN a hand holding the vehicle, then pushing it to 3 m/s up in 0.3 s WHEN released THEN it
// flies a ballistic arc with the motors off, and the IMU felt the push and then free fall.
TEST(ThrowHand, HoldsPushesAndReleases) {
  const VehicleParams v;
  Simulator sim(v, idealParams(), 1,
                stressFrom("{throw: {at: 1.0, hold_position: [0, 0, 1.2], velocity: [0, 0, 3], duration: 0.3}}"));
  double held_imu_z = 0.0;
  while (sim.utime() < 1000000) {
    const StepOutput o = sim.step();
    if (o.imu) held_imu_z = o.imu->accel.z();
  }
  EXPECT_EQ(sim.body().position, Vec3(0, 0, 1.2));
  EXPECT_EQ(sim.acceleration(), Vec3::Zero());
  EXPECT_NEAR(held_imu_z, kDefaultGravity, 0.6);  // +g, within bias and noise
  while (sim.utime() < 1200000) sim.step();
  EXPECT_NEAR(sim.acceleration().z(), 10.0, 1e-6);
  while (sim.utime() < 1300000) sim.step();
  EXPECT_NEAR(sim.body().velocity.z(), 3.0, 1e-9);
  EXPECT_NEAR(sim.body().position.z(), 1.2 + 0.45, 1e-9);
  while (sim.utime() < 1500000) sim.step();
  EXPECT_NEAR(sim.acceleration().z(), -kDefaultGravity, 1e-6);  // motors off: ballistic
  EXPECT_NEAR(sim.body().velocity.z(), 3.0 - kDefaultGravity * 0.2, 1e-6);
}

TEST(SimStress, BadKeysAndValuesNameTheKey) {
  const auto error_of = [](const std::string& yaml) {
    try {
      stressFrom(yaml);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of("{plant: {mass_scale: 3}}").find("sim.plant.mass_scale"), std::string::npos);
  EXPECT_NE(error_of("{plant: {mas_scale: 1.1}}").find("sim.plant.mas_scale"), std::string::npos);
  EXPECT_NE(error_of("{wind: {gust_std: [1, -1, 0]}}").find("sim.wind.gust_std[1]"), std::string::npos);
  EXPECT_NE(error_of("{airborne_start: {position: [0, 0, -1]}}").find("sim.airborne_start.position"),
            std::string::npos);
  EXPECT_NE(error_of("{throw: {at: 1, hold_position: [0, 0, 0]}}").find("sim.throw.hold_position"),
            std::string::npos);
  EXPECT_NE(error_of("{throw: {at: 1}, airborne_start: {position: [0, 0, 2]}}").find("sim.throw"), std::string::npos);
  EXPECT_EQ(error_of("{plant: {mass_scale: 1.2}}"), "no error");
}

}  // namespace
}  // namespace sdlqr::sim
