// The estimator allocates nothing after construction: onImu and onVio run in the 250 Hz / 1 kHz
// path. Every global operator new of this binary is counted (tests/support/allocation_counter).

#include <gtest/gtest.h>

#include <vector>


#include "allocation_counter.hpp"
#include "estimator_run.hpp"
#include "sdlqr/estimator/estimator.hpp"


namespace sdlqr::estimator::test {
namespace {

TEST(EstimatorAllocation, OnImuAndOnVioNeverAllocate) {
  // GIVEN a constructed estimator and an agile flight with a VIO dropout, a re-initialisation,
  // bad messages, a clipped accelerometer sample and a VIO frame jump (gated poses, a reset),
  // all generated beforehand
  SensorSimulator sensors{AnalyticTrajectory(TrajectorySpec()), SensorSpec()};
  std::vector<SensorEvent> events = sensors.run(12.0);
  for (SensorEvent& e : events) {
    if (e.kind == SensorEvent::Kind::kVio && e.vio.seq % 50 == 7) e.vio.orientation *= 2.0;  // rejected
    if (e.kind == SensorEvent::Kind::kVio && e.vio.utime >= 10'000'000) e.vio.position.x() += 0.3;
    if (e.kind == SensorEvent::Kind::kImu && e.imu.utime == 9'000'000) e.imu.accel.z() = 156.9;
  }
  Estimator estimator{EstimatorParams()};

  // WHEN every event is handed over with allocation counting on
  int64_t outputs = 0;
  const sdlqr::testing::AllocationCounter counter;
  for (const SensorEvent& e : events) {
    if (e.kind == SensorEvent::Kind::kImu) {
      if (estimator.onImu(e.imu)) ++outputs;
    } else if (e.vio.utime < 5'000'000 || e.vio.utime > 7'500'000) {  // 2.5 s gap: re-initialises
      estimator.onVio(e.vio);
    }
  }
  const long allocations = counter.count();

  // THEN nothing was allocated, and the run exercised what it should have
  std::cout << "[ measured ] " << allocations << " allocations over " << outputs << " outputs\n";
  EXPECT_EQ(allocations, 0);
  EXPECT_GT(outputs, 2900);
  EXPECT_EQ(estimator.counters().initializations, 2);
  EXPECT_EQ(estimator.counters().accel_clipping, 1);
  EXPECT_EQ(estimator.counters().vio_resets, 1);
  EXPECT_GT(estimator.counters().vioRejected(RejectReason::kQuaternionNorm), 0);
  EXPECT_GT(estimator.counters().vio_fused, 250);
}

TEST(EstimatorAllocation, TheCounterSeesAllocations) {
  // The zero above means something only if the replaced operator new is really in use.
  EXPECT_GE(sdlqr::testing::allocationsOfOneVector(), 2);
}

}  // namespace
}  // namespace sdlqr::estimator::test
