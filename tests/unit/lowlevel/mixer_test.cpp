// Allocation and desaturation: exact where the rotors can deliver, roll/pitch first where they
// cannot, never outside the rotor limits.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/mixer.hpp"

namespace sdlqr::lowlevel {
namespace {

class MixerTest : public ::testing::Test {
 protected:
  VehicleParams vehicle;
  Mixer mixer{vehicle.effectiveness(), 0.03, vehicle.max_rotor_thrust};
  double hover = vehicle.mass * 9.81;

  void expectWithinLimits(const MixerResult& r) {
    for (int i = 0; i < 4; ++i) {
      EXPECT_GE(r.thrust[i], mixer.minThrust()) << "rotor " << i;
      EXPECT_LE(r.thrust[i], mixer.maxThrust()) << "rotor " << i;
    }
  }
};

TEST_F(MixerTest, AllocationInvertsTheEffectiveness) {
  EXPECT_TRUE((mixer.effectiveness() * mixer.allocation()).isApprox(Mat44::Identity(), 1e-12));
}

TEST_F(MixerTest, FeasibleDemandsRoundTripExactly) {
  // Wrenches of rotor thrusts strictly inside the limits must come back as those thrusts.
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> thrust(0.05, 1.2);
  for (int trial = 0; trial < 1000; ++trial) {
    const Vec4 rotors(thrust(rng), thrust(rng), thrust(rng), thrust(rng));
    const Vec4 wrench = vehicle.effectiveness() * rotors;
    const MixerResult r = mixer.mix(wrench[0], wrench.tail<3>());
    ASSERT_TRUE(r.thrust.isApprox(rotors, 1e-9)) << r.thrust.transpose() << " vs " << rotors.transpose();
    EXPECT_NEAR(r.collective, wrench[0], 1e-9);
    EXPECT_TRUE(r.torque.isApprox(wrench.tail<3>(), 1e-9) || wrench.tail<3>().norm() < 1e-12);
    EXPECT_FALSE(r.saturated());
    EXPECT_EQ(r.roll_pitch_scale, 1.0);
    EXPECT_EQ(r.yaw_scale, 1.0);
  }
}

TEST_F(MixerTest, HoverThrustIsSplitEqually) {
  const MixerResult r = mixer.mix(hover, Vec3::Zero());
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(r.thrust[i], hover / 4.0, 1e-12);
  EXPECT_FALSE(r.saturated());
}

TEST_F(MixerTest, SaturationKeepsRollPitchAndGivesUpYawAndCollective) {
  // Near full thrust, with a strong roll/pitch demand and a yaw demand the rotors cannot add.
  const double collective = 4.6;                // [N] of 5.0 available
  const Vec3 torque(0.06, -0.04, 0.02);         // [N m]
  const MixerResult r = mixer.mix(collective, torque);
  expectWithinLimits(r);
  EXPECT_NEAR(r.torque.x(), torque.x(), 1e-9);
  EXPECT_NEAR(r.torque.y(), torque.y(), 1e-9);
  EXPECT_EQ(r.roll_pitch_scale, 1.0);
  EXPECT_LT(r.yaw_scale, 1.0);
  EXPECT_LT(std::abs(r.torque.z()), std::abs(torque.z()));
  EXPECT_GE(r.torque.z(), 0.0);  // reduced, never reversed
  EXPECT_LT(r.collective, collective);
  EXPECT_TRUE(r.collective_limited);
  EXPECT_TRUE(r.saturated_positive[2]);
  EXPECT_FALSE(r.saturated_positive[0] || r.saturated_negative[1]);
  std::cout << "desaturated: collective " << r.collective << " of " << collective << " N, yaw " << r.torque.z()
            << " of " << torque.z() << " N m, roll/pitch kept " << r.torque.head<2>().transpose() << "\n";
}

TEST_F(MixerTest, YawTakesAtMostItsShareOfTheCollective) {
  const double collective = 4.8;
  const MixerResult r = mixer.mix(collective, Vec3(0.0, 0.0, 0.5));  // far beyond yaw authority
  expectWithinLimits(r);
  EXPECT_GE(r.collective, (1.0 - MixerParams().yaw_collective_share) * collective - 1e-9);
  EXPECT_GT(r.torque.z(), 0.0);
  EXPECT_LT(r.yaw_scale, 1.0);
}

TEST_F(MixerTest, ImpossibleRollPitchIsScaledKeepingItsDirection) {
  const Vec3 torque(0.5, 0.3, 0.0);  // several times the roll/pitch authority
  const MixerResult r = mixer.mix(hover, torque);
  expectWithinLimits(r);
  EXPECT_LT(r.roll_pitch_scale, 1.0);
  EXPECT_GT(r.roll_pitch_scale, 0.0);
  // Same direction in the roll/pitch plane.
  const Eigen::Vector2d delivered = r.torque.head<2>();
  const Eigen::Vector2d demanded = torque.head<2>();
  EXPECT_NEAR(delivered.normalized().dot(demanded.normalized()), 1.0, 1e-9);
  EXPECT_NEAR(delivered.norm(), r.roll_pitch_scale * demanded.norm(), 1e-9);
  // Using the whole rotor range: one rotor at each limit.
  EXPECT_NEAR(r.thrust.maxCoeff(), mixer.maxThrust(), 1e-9);
  EXPECT_NEAR(r.thrust.minCoeff(), mixer.minThrust(), 1e-9);
  EXPECT_TRUE(r.saturated_positive[0] && r.saturated_positive[1]);
}

TEST_F(MixerTest, ZeroCollectiveStillDeliversTorque) {
  // The collective rises just enough for the torque (the vehicle must not tumble at low thrust).
  const MixerResult r = mixer.mix(0.0, Vec3(0.03, 0.0, 0.0));
  expectWithinLimits(r);
  EXPECT_NEAR(r.torque.x(), 0.03, 1e-9);
  EXPECT_TRUE(r.collective_limited);
}

TEST_F(MixerTest, NeverOutsideLimitsAndNeverReversesATorque) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> collective(-10.0, 20.0);
  std::uniform_real_distribution<double> torque(-2.0, 2.0);
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec3 demand(torque(rng), torque(rng), 0.2 * torque(rng));
    const MixerResult r = mixer.mix(collective(rng), demand);
    ASSERT_TRUE(r.thrust.allFinite());
    for (int i = 0; i < 4; ++i) {
      ASSERT_GE(r.thrust[i], mixer.minThrust());
      ASSERT_LE(r.thrust[i], mixer.maxThrust());
    }
    for (int axis = 0; axis < 3; ++axis) ASSERT_GE(r.torque[axis] * demand[axis], -1e-12) << "axis " << axis;
  }
}

TEST_F(MixerTest, NonFiniteDemandGivesMinimumThrust) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const MixerResult& r : {mixer.mix(nan, Vec3::Zero()), mixer.mix(hover, Vec3(0.0, nan, 0.0)),
                               mixer.mix(std::numeric_limits<double>::infinity(), Vec3::Zero())}) {
    EXPECT_EQ(r.thrust, Vec4::Constant(mixer.minThrust()));
    EXPECT_TRUE(r.saturated());
  }
}

TEST(MixerGeometry, RejectsLayoutsWhereARotorMustPushDown) {
  // All rotors ahead of the centre of mass: holding zero pitch torque needs a negative thrust.
  VehicleParams vehicle;
  vehicle.rotor_xy << 0.2, 0.05, 0.2, 0.05,
                      -0.1, 0.1, 0.1, -0.1;
  EXPECT_THROW(Mixer(vehicle.effectiveness(), 0.0, 1.0), std::invalid_argument);
  EXPECT_THROW(Mixer(VehicleParams().effectiveness(), 1.0, 1.0), std::invalid_argument);
}

TEST(MixerParams, ShareOutsideUnitIntervalIsInvalid) {
  MixerParams params;
  params.yaw_collective_share = 1.5;
  EXPECT_EQ(params.invalidReason().rfind("yaw_collective_share:", 0), 0u);
  EXPECT_TRUE(MixerParams().valid());
}

}  // namespace
}  // namespace sdlqr::lowlevel
