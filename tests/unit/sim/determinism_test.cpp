// Same seed and inputs give the same flight bit for bit; step() never allocates.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include "allocation_counter.hpp"
#include "sim_test_support.hpp"


namespace sdlqr::sim {
namespace {

using test::armed;
using test::hoverThrust;

// A scripted flight: take off, pull, land; every output recorded.
struct Recording {
  std::vector<SimTruth> truth;
  std::vector<ImuSample> imu;
  std::vector<VioPose> vio;
};

Recording fly(uint64_t seed) {
  const VehicleParams v;
  Simulator sim(v, SimParams(), seed);
  Recording r;
  Disturbance pull;
  pull.start_utime = 1500000;
  pull.duration = 0.5;
  pull.force = Vec3(0.3, -0.2, 0.0);
  pull.torque = Vec3(0.001, 0.0, -0.0005);
  sim.addDisturbance(pull);
  for (int i = 0; i < 4000; ++i) {
    if (i % 10 == 0) {
      // Rotor commands that change over time, as a controller's would.
      const double k = i < 2500 ? 1.15 : 0.9;
      const Vec4 wobble(0.01 * std::sin(i * 0.01), -0.01 * std::sin(i * 0.01), 0.005, -0.005);
      sim.setMotorCommand(armed(k * hoverThrust(v) + wobble));
    }
    const StepOutput out = sim.step();
    if (out.truth) r.truth.push_back(*out.truth);
    if (out.imu) r.imu.push_back(*out.imu);
    if (out.vio) r.vio.push_back(*out.vio);
  }
  return r;
}

bool sameBits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 3) == 0; }
bool sameBits(const Vec4& a, const Vec4& b) { return std::memcmp(a.data(), b.data(), sizeof(double) * 4) == 0; }

TEST(Determinism, SameSeedAndInputsGiveTheSameFlightBitForBit) {
  const Recording a = fly(42);
  const Recording b = fly(42);
  ASSERT_EQ(a.truth.size(), b.truth.size());
  ASSERT_EQ(a.imu.size(), b.imu.size());
  ASSERT_EQ(a.vio.size(), b.vio.size());
  double highest = 0.0;
  for (const SimTruth& t : a.truth) highest = std::max(highest, t.position.z());
  ASSERT_GT(highest, 0.3);  // the flight really flew
  for (size_t i = 0; i < a.truth.size(); ++i) {
    ASSERT_TRUE(sameBits(a.truth[i].position, b.truth[i].position)) << i;
    ASSERT_TRUE(sameBits(a.truth[i].orientation, b.truth[i].orientation)) << i;
    ASSERT_TRUE(sameBits(a.truth[i].velocity, b.truth[i].velocity)) << i;
    ASSERT_TRUE(sameBits(a.truth[i].rotor_thrust, b.truth[i].rotor_thrust)) << i;
    ASSERT_EQ(a.truth[i].battery_voltage, b.truth[i].battery_voltage) << i;
  }
  for (size_t i = 0; i < a.imu.size(); ++i) {
    ASSERT_TRUE(sameBits(a.imu[i].gyro, b.imu[i].gyro)) << i;
    ASSERT_TRUE(sameBits(a.imu[i].accel, b.imu[i].accel)) << i;
  }
  for (size_t i = 0; i < a.vio.size(); ++i) {
    ASSERT_EQ(a.vio[i].publish_utime, b.vio[i].publish_utime) << i;
    ASSERT_TRUE(sameBits(a.vio[i].position, b.vio[i].position)) << i;
    ASSERT_TRUE(sameBits(a.vio[i].orientation, b.vio[i].orientation)) << i;
  }
}

TEST(Determinism, DifferentSeedChangesTheNoiseButNotThePhysics) {
  const Recording a = fly(1);
  const Recording b = fly(2);
  // The plant does not depend on the sensor noise...
  ASSERT_EQ(a.truth.size(), b.truth.size());
  EXPECT_TRUE(sameBits(a.truth.back().position, b.truth.back().position));
  // ...the sensors do.
  // Every unclipped reading differs (at touchdown both clip to the same full-scale value).
  const double range = SimParams().imu.accel_range;
  int compared = 0, differing = 0;
  for (size_t i = 0; i < a.imu.size(); ++i) {
    if (a.imu[i].accel.cwiseAbs().maxCoeff() >= range || b.imu[i].accel.cwiseAbs().maxCoeff() >= range) continue;
    ++compared;
    differing += !sameBits(a.imu[i].accel, b.imu[i].accel);
  }
  EXPECT_GT(compared, 3900);
  EXPECT_EQ(differing, compared);
  EXPECT_FALSE(sameBits(a.vio.front().position, b.vio.front().position));
  EXPECT_NE(a.vio.front().publish_utime - a.vio.front().utime + a.vio[1].publish_utime - a.vio[1].utime,
            b.vio.front().publish_utime - b.vio.front().utime + b.vio[1].publish_utime - b.vio[1].utime);
}

TEST(Allocation, StepAllocatesNothing) {
  const VehicleParams v;
  Simulator sim(v, SimParams());
  Disturbance hold;
  hold.mode = DisturbanceMode::kHold;
  hold.duration = 100.0;
  hold.hold_stiffness = 5.0;
  hold.hold_damping = 1.0;
  sim.addDisturbance(hold);
  sim.setMotorCommand(armed(1.1 * hoverThrust(v)));
  int outputs = 0;
  const long before = sdlqr::testing::allocationCount();
  for (int i = 0; i < 5000; ++i) {
    if (i % 10 == 0) sim.setMotorCommand(armed((1.1 + 0.01 * (i % 7)) * hoverThrust(v)));
    const StepOutput out = sim.step();
    outputs += out.imu.has_value() + out.vio.has_value() + out.truth.has_value();
  }
  const long allocations = sdlqr::testing::allocationCount() - before;
  std::cout << "allocations in 5000 steps (" << outputs << " outputs): " << allocations << "\n";
  EXPECT_GT(outputs, 5000);
  EXPECT_EQ(allocations, 0);
}

TEST(Allocation, CounterSeesAllocations) {
  // Guards the test above: the counter must be live in this binary.
  EXPECT_GE(sdlqr::testing::allocationsOfOneVector(), 2);
}

}  // namespace
}  // namespace sdlqr::sim
