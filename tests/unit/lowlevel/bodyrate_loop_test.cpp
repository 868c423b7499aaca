// Arming state machine, input rejection and the NaN guard of the bodyrate loop, on IMU
// samples of a vehicle resting on the ground (no plant needed).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "sdlqr/lowlevel/bodyrate_loop.hpp"

namespace sdlqr::lowlevel {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

class LoopTest : public ::testing::Test {
 protected:
  VehicleParams vehicle;
  LowlevelParams params;
  ValidationLimits limits;
  BodyrateLoop loop{vehicle, params, limits};
  int64_t utime = 1'000'000;
  int64_t seq = 0;

  ImuSample restingSample() {
    ImuSample s;
    s.utime = utime;
    s.seq = seq;
    s.accel = Vec3(0.0, 0.0, 9.81);
    return s;
  }
  MotorCommand tick() {
    utime += 1000;
    ++seq;
    return loop.step(restingSample());
  }
  RateCommand rate(const Vec3& omega, double thrust, int64_t at) {
    RateCommand c;
    c.utime = at;
    c.body_rate = omega;
    c.thrust = thrust;
    return c;
  }
  bool command(CommandType type) {
    Command c;
    c.command = type;
    return loop.handleCommand(c);
  }
  int64_t rateRejected(RejectReason reason) const {
    return loop.counters().rate_cmd_rejected[static_cast<size_t>(reason)];
  }
  int64_t imuRejected(RejectReason reason) const { return loop.counters().imu_rejected[static_cast<size_t>(reason)]; }
};

TEST_F(LoopTest, StartsDisarmedWithZeroThrustStampedWithTheSample) {
  const MotorCommand out = tick();
  EXPECT_EQ(out.mode, MotorMode::kDisarmed);
  EXPECT_FALSE(out.armed);
  EXPECT_EQ(out.thrust, Vec4::Zero());
  EXPECT_EQ(out.utime, utime);
  EXPECT_EQ(out.imu_seq, seq);
}

TEST_F(LoopTest, ArmingNeedsAnImuSample) {
  EXPECT_FALSE(command(CommandType::kArm));
  EXPECT_EQ(loop.counters().arm_refused, 1);
  tick();
  EXPECT_TRUE(command(CommandType::kArm));
  EXPECT_EQ(tick().mode, MotorMode::kIdle);
}

TEST_F(LoopTest, IdleSpinsTheRotorsAtIdleThrustAndWaitsWithoutFailsafe) {
  tick();
  command(CommandType::kArm);
  for (int i = 0; i < 2000; ++i) {
    const MotorCommand out = tick();
    ASSERT_EQ(out.mode, MotorMode::kIdle);
    ASSERT_TRUE(out.armed);
    ASSERT_EQ(out.thrust, Vec4::Constant(params.idle_thrust));
  }
}

TEST_F(LoopTest, FreshRateCommandAfterArmingStartsRateMode) {
  tick();
  ASSERT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime)), RejectReason::kNone);
  command(CommandType::kArm);
  EXPECT_EQ(tick().mode, MotorMode::kIdle);  // the command before arming does not count
  ASSERT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime)), RejectReason::kNone);
  const MotorCommand out = tick();
  EXPECT_EQ(out.mode, MotorMode::kRate);
  EXPECT_NEAR(out.thrust.sum(), vehicle.mass * 9.81, 0.05);
}

TEST_F(LoopTest, TakeoffArmsAndDisarmStopsTheRotorsFromAnyMode) {
  tick();
  EXPECT_TRUE(command(CommandType::kTakeoff));
  EXPECT_EQ(tick().mode, MotorMode::kIdle);
  loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime));
  EXPECT_EQ(tick().mode, MotorMode::kRate);
  EXPECT_TRUE(command(CommandType::kArm));  // already armed: no change
  EXPECT_EQ(tick().mode, MotorMode::kRate);
  EXPECT_TRUE(command(CommandType::kDisarm));
  const MotorCommand out = tick();
  EXPECT_EQ(out.mode, MotorMode::kDisarmed);
  EXPECT_EQ(out.thrust, Vec4::Zero());
  // A later RATE_CMD does not re-arm.
  loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime));
  EXPECT_EQ(tick().mode, MotorMode::kDisarmed);
}

TEST_F(LoopTest, LandWhileIdleDisarmsAndGotoChangesNothing) {
  tick();
  command(CommandType::kArm);
  EXPECT_TRUE(command(CommandType::kGoto));
  EXPECT_EQ(tick().mode, MotorMode::kIdle);
  EXPECT_TRUE(command(CommandType::kLand));
  EXPECT_EQ(tick().mode, MotorMode::kDisarmed);
}

TEST_F(LoopTest, UnknownCommandIsRefused) {
  tick();
  Command c;
  c.command = static_cast<CommandType>(42);
  EXPECT_FALSE(loop.handleCommand(c));
  EXPECT_EQ(tick().mode, MotorMode::kDisarmed);
}

TEST_F(LoopTest, RateModeTimesOutIntoFailsafe) {
  tick();
  command(CommandType::kArm);
  loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime));
  tick();
  int ticks = 0;
  while (tick().mode == MotorMode::kRate && ticks < 1000) ++ticks;
  // The last command is older than rate_cmd_timeout after 100 samples of 1 ms.
  EXPECT_NEAR(ticks + 1, 100, 1);
  EXPECT_EQ(loop.mode(), MotorMode::kFailsafe);
  EXPECT_EQ(loop.counters().failsafe_entries, 1);
}

TEST_F(LoopTest, InvalidRateCommandsAreRejectedAndCounted) {
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime)), RejectReason::kNoClock);
  tick();
  EXPECT_EQ(loop.setRateCommand(rate(Vec3(kNan, 0, 0), 9.81, utime)), RejectReason::kNonFinite);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), kInf, utime)), RejectReason::kNonFinite);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3(0, -(limits.max_body_rate + 1.0), 0), 9.81, utime)),
            RejectReason::kOutOfRange);
  // The bound is on |omega|, as in every validator: within it on each axis is not enough.
  const double per_axis = 0.8 * limits.max_body_rate;
  EXPECT_EQ(loop.setRateCommand(rate(Vec3(per_axis, per_axis, 0), 9.81, utime)), RejectReason::kOutOfRange);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), -0.1, utime)), RejectReason::kOutOfRange);
  const double max_thrust = 4.0 * vehicle.max_rotor_thrust / vehicle.mass;
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), max_thrust + 0.1, utime)), RejectReason::kOutOfRange);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime + 500'000)), RejectReason::kTimeFuture);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime - 500'000)), RejectReason::kStale);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, std::numeric_limits<int64_t>::max())),
            RejectReason::kTimeFuture);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), max_thrust, utime)), RejectReason::kNone);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime - 1000)), RejectReason::kTimeBackwards);
  EXPECT_EQ(loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime)), RejectReason::kNone);  // same time is fine

  EXPECT_EQ(rateRejected(RejectReason::kNoClock), 1);
  EXPECT_EQ(rateRejected(RejectReason::kNonFinite), 2);
  EXPECT_EQ(rateRejected(RejectReason::kOutOfRange), 4);
  EXPECT_EQ(rateRejected(RejectReason::kTimeFuture), 2);
  EXPECT_EQ(rateRejected(RejectReason::kStale), 1);
  EXPECT_EQ(rateRejected(RejectReason::kTimeBackwards), 1);
  EXPECT_EQ(loop.counters().rate_cmd_accepted, 2);
}

TEST_F(LoopTest, RejectedRateCommandNeverReachesTheRotors) {
  tick();
  command(CommandType::kArm);
  loop.setRateCommand(rate(Vec3::Zero(), 9.81, utime));
  const MotorCommand before = tick();
  ASSERT_EQ(before.mode, MotorMode::kRate);
  loop.setRateCommand(rate(Vec3(kNan, 0, 0), kNan, utime));
  loop.setRateCommand(rate(Vec3::Zero(), 1e9, utime));
  const MotorCommand after = tick();
  EXPECT_TRUE(after.thrust.isApprox(before.thrust, 1e-3));
}

TEST_F(LoopTest, InvalidImuSamplesAreRejectedCountedAndChangeNothing) {
  const MotorCommand first = tick();
  ImuSample bad = restingSample();
  bad.utime = utime + 1000;
  bad.gyro.y() = kNan;
  MotorCommand out = loop.step(bad);
  EXPECT_EQ(loop.lastImuReject(), RejectReason::kNonFinite);
  EXPECT_EQ(out.seq, first.seq);  // the previous command, untouched
  bad = restingSample();
  bad.utime = utime + 1000;
  bad.accel.x() = 1e4;
  loop.step(bad);
  EXPECT_EQ(loop.lastImuReject(), RejectReason::kOutOfRange);
  bad = restingSample();
  bad.utime = utime;  // not newer
  loop.step(bad);
  EXPECT_EQ(loop.lastImuReject(), RejectReason::kTimeBackwards);
  bad.utime = utime + 5'000'000;
  loop.step(bad);
  EXPECT_EQ(loop.lastImuReject(), RejectReason::kTimeGap);
  EXPECT_EQ(imuRejected(RejectReason::kNonFinite), 1);
  EXPECT_EQ(imuRejected(RejectReason::kOutOfRange), 1);
  EXPECT_EQ(imuRejected(RejectReason::kTimeBackwards), 1);
  EXPECT_EQ(imuRejected(RejectReason::kTimeGap), 1);
  EXPECT_EQ(loop.counters().imu_accepted, 1);
  tick();
  EXPECT_EQ(loop.lastImuReject(), RejectReason::kNone);
  EXPECT_EQ(loop.counters().imu_accepted, 2);
}

TEST_F(LoopTest, RestartedClockIsAdoptedAfterARunOfRejects) {
  for (int i = 0; i < 10; ++i) tick();
  utime = 0;  // the publisher restarted its clock
  int rejected_samples = 0;
  while (rejected_samples < 1000) {
    tick();
    if (loop.lastImuReject() == RejectReason::kNone) break;
    ++rejected_samples;
  }
  EXPECT_EQ(rejected_samples, 99);
  EXPECT_EQ(loop.counters().imu_resyncs, 1);
  tick();
  EXPECT_EQ(loop.lastImuReject(), RejectReason::kNone);
}

TEST_F(LoopTest, MassUpdateScalesTheCollectiveAndRejectsNonsense) {
  tick();
  command(CommandType::kArm);
  loop.setRateCommand(rate(Vec3::Zero(), 9.0, utime));
  const double before = tick().thrust.sum();
  EXPECT_TRUE(loop.setMass(0.3));
  const double after = tick().thrust.sum();
  EXPECT_NEAR(after / before, 0.3 / vehicle.mass, 1e-3);
  EXPECT_FALSE(loop.setMass(-1.0));
  EXPECT_FALSE(loop.setMass(kNan));
  EXPECT_FALSE(loop.setMass(10.0));  // cannot hover on these rotors
  EXPECT_EQ(loop.counters().mass_rejected, 3);
  EXPECT_EQ(loop.mass(), 0.3);
}

TEST_F(LoopTest, GarbageInputsNeverProduceNonFiniteOrOutOfRangeThrust) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 39);  // one value in ten is wild
  auto wild = [&](double scale) {
    switch (pick(rng)) {
      case 0: return kNan;
      case 1: return kInf;
      case 2: return -kInf;
      case 3: return 1e300;
      default: return scale * uniform(rng);
    }
  };
  auto wildTime = [&]() -> int64_t {
    switch (pick(rng)) {
      case 0: return std::numeric_limits<int64_t>::min();
      case 1: return std::numeric_limits<int64_t>::max();
      case 2: return utime - 1'000'000;
      default: return utime + static_cast<int64_t>(2e5 * uniform(rng));
    }
  };
  tick();
  command(CommandType::kArm);
  for (int i = 0; i < 20000; ++i) {
    if (i % 7 == 0) loop.setRateCommand(rate(Vec3(wild(25), wild(25), wild(25)), wild(25), wildTime()));
    if (i % 997 == 0) loop.setMass(wild(1.0));
    if (i % 1500 == 0) command(CommandType::kArm);
    ImuSample s = restingSample();
    utime += 1000;
    s.utime = pick(rng) == 0 ? utime - 5000 : utime;
    s.gyro = Vec3(wild(40), wild(40), wild(40));
    s.accel = Vec3(wild(20), wild(20), 9.81 + wild(20));
    const MotorCommand out = loop.step(s);
    ASSERT_TRUE(out.thrust.allFinite()) << "step " << i;
    ASSERT_GE(out.thrust.minCoeff(), 0.0);
    ASSERT_LE(out.thrust.maxCoeff(), vehicle.max_rotor_thrust);
  }
  EXPECT_EQ(loop.counters().nonfinite_outputs, 0);
  EXPECT_GT(loop.counters().imu_accepted, 5000);
  EXPECT_GT(loop.counters().rate_cmd_accepted, 10);
}

TEST(LoopConstruction, RejectsInvalidParameters) {
  LowlevelParams params;
  params.idle_thrust = 2.0;  // above the rotor's maximum
  const ValidationLimits limits;
  EXPECT_THROW(BodyrateLoop(VehicleParams(), params, limits), std::invalid_argument);
  VehicleParams vehicle;
  vehicle.mass = -1.0;
  EXPECT_THROW(BodyrateLoop(vehicle, LowlevelParams(), limits), std::invalid_argument);
  EXPECT_NO_THROW(BodyrateLoop(VehicleParams(), LowlevelParams(), limits));
}

TEST(LoopConstruction, TheFailsafeStaysWithinTheStacksBodyRateLimit) {
  LowlevelParams params;
  ValidationLimits limits;
  limits.max_body_rate = 0.5 * params.failsafe.max_rate;
  try {
    BodyrateLoop loop(VehicleParams(), params, limits);
    ADD_FAILURE() << "a failsafe levelling faster than the accepted body rate was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("lowlevel.failsafe.max_rate"), std::string::npos) << e.what();
  }
  limits.max_body_rate = params.failsafe.max_rate;
  EXPECT_NO_THROW(BodyrateLoop(VehicleParams(), params, limits));
}

}  // namespace
}  // namespace sdlqr::lowlevel
