// The 100 Hz tick (StateDependentLqr::onStateEstimate) and the 10 Hz solve (GainScheduler) allocate
// nothing once running: counted by the replaced operator new of tests/support, over hover ticks,
// fresh/stale/fallback gains, and spatial and temporal tracking of the paper's fast trajectory.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <vector>

#include "allocation_counter.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/gains/gain_scheduler.hpp"
#include "sdlqr/controller/state_dependent_lqr.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"

namespace sdlqr::controller {
namespace {

StateEstimate estimateAt(int64_t utime, const Vec3& p) {
  StateEstimate e;
  e.utime = utime;
  e.seq = utime / 4000;
  e.position = p;
  e.status = EstimatorStatus::kOk;
  return e;
}

Command command(CommandType type, const Vec3& position) {
  Command c;
  c.command = type;
  c.position = position;
  return c;
}

// A controller taken off toward (0, 0, 1) beside its gain solver.
class ControllerAllocation : public ::testing::Test {
 protected:
  ControllerAllocation() {
    controller.onStateEstimate(estimateAt(0, Vec3::Zero()), tick);
    controller.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1)));
  }

  // 250 Hz estimates on a slow loop at 1 m from `from` to `to` [us]: each to the controller, and to
  // the gain solver when it is due and with_gains (its gains then to the controller).
  void fly(int64_t from, int64_t to, bool with_gains = true) {
    for (int64_t utime = from; utime < to; utime += 4000) {
      const double t = 1e-6 * static_cast<double>(utime);
      const StateEstimate e = estimateAt(utime, Vec3(0.3 * std::sin(t), 0.2 * std::cos(t), 1.0));
      if (with_gains && scheduler.due(e)) {
        GainSet gains;
        if (scheduler.solve(e, gains) == SolveStatus::kOk) {
          controller.setGains(gains);
          ++solves;
        }
      }
      if (controller.onStateEstimate(e, tick)) {
        scheduler.setReference(tick.reference);
        ++ticks;
      }
    }
  }

  const LqrParams lqr;
  StateDependentLqr controller{lqr, ControllerParams{}};
  gains::GainScheduler scheduler{lqr, 10.0};
  StateDependentLqr::Tick tick;
  int64_t ticks = 0;
  int64_t solves = 0;
};

TEST_F(ControllerAllocation, TicksAndSolvesAllocateNothing) {
  const Trajectory fast = trajectory::sampleTrajectory(trajectory::paperMinSnapFast(trajectory::TrajectoryParams{}),
                                                       0.1, lqr.gravity);
  ASSERT_GT(fast.samples.size(), 50u);

  const sdlqr::testing::AllocationCounter counter;
  fly(4000, 3'000'000, true);      // take-off and hold with fresh gains
  fly(3'000'000, 5'000'000, false);  // gains stop: stale, then the fallback hover K
  const long hover_allocations = counter.count();

  ASSERT_EQ(controller.setTrajectory(fast), "");  // copies the samples: allowed, on receipt
  const sdlqr::testing::AllocationCounter tracking_counter;
  fly(5'000'000, 12'000'000, true);
  ParamsUpdate temporal;
  temporal.field_mask = ParamsUpdate::kTracking;
  temporal.tracking = ReferenceMode::kTemporal;
  controller.applyParams(temporal);
  fly(12'000'000, 18'000'000, true);
  const long tracking_allocations = tracking_counter.count();

  std::cout << "[ measured ] " << hover_allocations << " + " << tracking_allocations << " allocations over "
            << ticks << " ticks and " << solves << " solves\n";
  EXPECT_EQ(hover_allocations, 0);
  EXPECT_EQ(tracking_allocations, 0);
  EXPECT_GT(ticks, 1700);
  EXPECT_GT(solves, 150);
  EXPECT_GT(controller.status().fallback_ticks, 0);
  EXPECT_GT(controller.status().stale_ticks, 0);
}

// Every law of the family, switched in through PARAMS (with its bumpless transfer), its solver's
// model in the scheduler too (the extensions' 12- and 10-state solves).
TEST_F(ControllerAllocation, EveryLawTicksAndSolvesWithoutAllocating) {
  fly(4000, 3'000'000);
  const sdlqr::testing::AllocationCounter counter;
  int64_t utime = 3'000'000;
  int64_t seq = 0;
  for (ControlLaw law : {ControlLaw::kHoverLqr, ControlLaw::kGeometric, ControlLaw::kSdlqrIntegral,
                         ControlLaw::kSdlqrActuator, ControlLaw::kSdlqr}) {
    ParamsUpdate update;
    update.utime = utime;
    update.seq = seq++;
    update.field_mask = ParamsUpdate::kLaw;
    update.law = law;
    ASSERT_EQ(scheduler.applyParams(update), ParamsOutcome::kApplied);
    ASSERT_EQ(controller.applyParams(update), ParamsOutcome::kApplied);
    fly(utime, utime + 2'000'000);
    utime += 2'000'000;
    EXPECT_EQ(controller.status().law, law);
  }
  std::cout << "[ measured ] " << counter.count() << " allocations over " << ticks << " ticks and " << solves
            << " solves of every law\n";
  EXPECT_EQ(counter.count(), 0);
  EXPECT_GE(controller.status().law_switches, 5);
}

TEST_F(ControllerAllocation, TheCounterSeesAllocations) {
  EXPECT_GE(sdlqr::testing::allocationsOfOneVector(), 2);
}

}  // namespace
}  // namespace sdlqr::controller
