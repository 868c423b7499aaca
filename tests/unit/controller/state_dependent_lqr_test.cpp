// The 100 Hz controller: tick scheduling in simulation time, gain freshness (docs/architecture.md
// §4, §7: keep the last valid K, flag it stale, fall back to a hover K after a timeout),
// parameter updates.

#include <gtest/gtest.h>

#include <vector>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/state_dependent_lqr.hpp"
#include "controller_test_commands.hpp"

namespace sdlqr::controller {
namespace {

using test::command;

StateEstimate estimateAt(int64_t utime, const Vec3& p, const Quat& q = identityQuat()) {
  StateEstimate e;
  e.utime = utime;
  e.seq = utime / 4000;
  e.position = p;
  e.orientation = q;
  e.status = EstimatorStatus::kOk;
  return e;
}

// Brings a controller to a held setpoint at (0, 0, 1) with the given yaw after take-off.
void takeOffAndHold(StateDependentLqr& controller, double yaw = 0.0) {
  StateDependentLqr::Tick tick;
  controller.onStateEstimate(estimateAt(0, Vec3::Zero()), tick);
  controller.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1)));
  controller.onStateEstimate(estimateAt(10000, Vec3::Zero()), tick);
  Command hold = command(CommandType::kGoto, Vec3(0, 0, 1), yaw);
  hold.seq = 1;  // the take-off was seq 0: the same seq would be a re-send of it
  controller.handleCommand(hold);
}

// Feeds 1 s of 250 Hz estimates at (0, 0, 1), from 20 ms on, to a controller that took off and
// holds; calls check(the estimate's utime, the tick, the previous tick's utime or -1) on each tick.
// Returns the number of ticks.
template <class Check>
int ticksOverOneSecond(StateDependentLqr& controller, Check check) {
  takeOffAndHold(controller);
  StateDependentLqr::Tick tick;
  int ticks = 0;
  int64_t last = -1;
  for (int64_t utime = 20000; utime < 1020000; utime += 4000) {
    if (!controller.onStateEstimate(estimateAt(utime, Vec3(0, 0, 1)), tick)) continue;
    ++ticks;
    check(utime, tick, last);
    last = tick.command.utime;
  }
  return ticks;
}

TEST(StateDependentLqr, TicksExactlyEvery10msFromTheLastOfA250HzEstimateBeforeTheTick) {
  const LqrParams lqr;
  StateDependentLqr controller(lqr, ControllerParams{});
  const int ticks = ticksOverOneSecond(controller, [](int64_t utime, const StateDependentLqr::Tick& tick, int64_t last) {
    EXPECT_EQ(tick.command.utime % 10000, 0) << "on the 10 ms grid";
    EXPECT_EQ(tick.command.state_seq, utime / 4000) << "computed from this estimate";
    EXPECT_GE(tick.command.utime, utime);
    EXPECT_LT(tick.command.utime - utime, 4000) << "the newest estimate before the tick";
    EXPECT_EQ(tick.reference.utime, tick.command.utime);
    if (last >= 0) {
      EXPECT_EQ(tick.command.utime - last, 10000);
    }
  });
  EXPECT_EQ(ticks, 100);
  EXPECT_EQ(controller.status().predicted_ticks, 50) << "every other tick falls between two estimates";
}

TEST(StateDependentLqr, WithoutPredictionTicksOnTheFirstEstimateAtOrAfterTheTick) {
  const LqrParams lqr;
  ControllerParams params;
  params.max_prediction_s = 0.0;
  StateDependentLqr controller(lqr, params);
  const int ticks = ticksOverOneSecond(controller, [](int64_t utime, const StateDependentLqr::Tick& tick, int64_t last) {
    EXPECT_EQ(tick.command.utime, utime);
    if (last >= 0) {
      EXPECT_GE(tick.command.utime - last, 8000);
      EXPECT_LE(tick.command.utime - last, 12000);
    }
  });
  EXPECT_EQ(ticks, 100);
  EXPECT_EQ(controller.status().predicted_ticks, 0);
}

TEST(StateDependentLqr, MissingEstimatesMakeALateTickAtTheEstimateTimeThenTheGridResumes) {
  const LqrParams lqr;
  StateDependentLqr controller(lqr, ControllerParams{});
  takeOffAndHold(controller);
  StateDependentLqr::Tick tick;
  std::vector<int64_t> tick_times;
  for (int64_t utime = 20000; utime < 100000; utime += 4000) {
    if (utime > 40000 && utime < 64000) continue;  // 40 .. 64 ms: nothing arrives
    if (controller.onStateEstimate(estimateAt(utime, Vec3(0, 0, 1)), tick)) tick_times.push_back(tick.command.utime);
  }
  const std::vector<int64_t> expected = {20000, 30000, 40000, 64000, 70000, 80000, 90000};
  EXPECT_EQ(tick_times, expected);
}

TEST(StateDependentLqr, WithoutGainsTheYawedHoverFallbackEqualsTheSolverAtThatYaw) {
  const LqrParams lqr;
  const double yaw = 2.0;
  StateDependentLqr controller(lqr, ControllerParams{});
  takeOffAndHold(controller, yaw);
  StateDependentLqr::Tick tick;
  const Quat q_ref = quat::fromYaw(yaw);
  const Quat q = quat::multiply(q_ref, quat::exp(Vec3(0.02, -0.03, 0.01)));
  const Vec3 p(0.1, -0.05, 0.97);
  ASSERT_TRUE(controller.onStateEstimate(estimateAt(100000, p, q), tick));
  EXPECT_EQ(tick.command.gains_status, GainsFreshness::kFallback);
  EXPECT_EQ(tick.command.gains_seq, -1);

  const State x_ref = makeState(Vec3(0, 0, 1), q_ref, Vec3::Zero());
  const LqrResult at_yaw = solveLqr(x_ref, makeInput(Vec3::Zero(), lqr.gravity), lqr);
  ASSERT_EQ(at_yaw.status, SolveStatus::kOk);
  const Input expected = makeInput(Vec3::Zero(), lqr.gravity) + at_yaw.K * (makeState(p, q, Vec3::Zero()) - x_ref);
  EXPECT_LT((tick.command.input() - expected).norm(), 1e-9) << tick.command.input().transpose() << "\n"
                                                            << expected.transpose();
}

TEST(StateDependentLqr, KeepsTheLastGainFlagsItStaleThenFallsBack) {
  const LqrParams lqr;
  ControllerParams params;
  StateDependentLqr controller(lqr, ControllerParams{});
  takeOffAndHold(controller);
  GainSet gains;
  gains.utime = 20000;
  gains.seq = 7;
  gains.K = solveLqr(makeState(Vec3(0, 0, 1), identityQuat(), Vec3::Zero()), makeInput(Vec3::Zero(), 9.81), lqr).K;
  gains.K(3, 2) *= 2.0;  // recognisable
  controller.setGains(gains);
  StateDependentLqr::Tick tick;
  const Vec3 p(0, 0, 0.9);

  ASSERT_TRUE(controller.onStateEstimate(estimateAt(20000 + 100000, p), tick));
  EXPECT_EQ(tick.command.gains_status, GainsFreshness::kFresh);
  EXPECT_EQ(tick.command.gains_seq, 7);
  const double fresh_thrust = tick.command.thrust;

  ASSERT_TRUE(controller.onStateEstimate(estimateAt(20000 + 500000, p), tick));
  EXPECT_EQ(tick.command.gains_status, GainsFreshness::kStale);
  EXPECT_EQ(tick.command.gains_seq, 7);
  EXPECT_EQ(tick.command.thrust, fresh_thrust) << "the last valid K stays in use";

  ASSERT_TRUE(controller.onStateEstimate(estimateAt(20000 + static_cast<int64_t>(params.gains_fallback_s * 1e6) + 20000, p), tick));
  EXPECT_EQ(tick.command.gains_status, GainsFreshness::kFallback);
  EXPECT_EQ(tick.command.gains_seq, -1);
  EXPECT_NE(tick.command.thrust, fresh_thrust);
  EXPECT_GT(controller.status().fallback_ticks, 0);
  EXPECT_GT(controller.status().stale_ticks, 0);

  // Fresh gains take over again at once; an older solve arriving late is ignored.
  gains.utime = 1500000;
  gains.seq = 8;
  controller.setGains(gains);
  GainSet late = gains;
  late.utime = 1000000;
  late.seq = 6;
  controller.setGains(late);
  ASSERT_TRUE(controller.onStateEstimate(estimateAt(1520000, p), tick));
  EXPECT_EQ(tick.command.gains_status, GainsFreshness::kFresh);
  EXPECT_EQ(tick.command.gains_seq, 8);
}

TEST(StateDependentLqr, NoCommandBeforeTheEstimatorIsInitialisedOrWhileIdle) {
  StateDependentLqr controller(LqrParams{}, ControllerParams{});
  StateDependentLqr::Tick tick;
  StateEstimate e = estimateAt(0, Vec3::Zero());
  EXPECT_FALSE(controller.onStateEstimate(e, tick)) << "idle on the ground";
  controller.handleCommand(command(CommandType::kTakeoff, Vec3(0, 0, 1)));
  e = estimateAt(20000, Vec3::Zero());
  e.status = EstimatorStatus::kInitializing;
  EXPECT_FALSE(controller.onStateEstimate(e, tick));
  e = estimateAt(40000, Vec3::Zero());
  EXPECT_TRUE(controller.onStateEstimate(e, tick));
}

TEST(StateDependentLqr, LimitsFromParamsApplyAtTheNextTickAndInvalidOnesAreIgnored) {
  const LqrParams lqr;
  StateDependentLqr controller(lqr, ControllerParams{});
  takeOffAndHold(controller);
  StateDependentLqr::Tick tick;
  const Vec3 far(2.0, 0.0, 1.0);  // a large error: rates saturate
  ASSERT_TRUE(controller.onStateEstimate(estimateAt(100000, far), tick));
  EXPECT_NEAR(tick.command.body_rate.norm(), 2.0, 1e-9);

  ParamsUpdate update;
  update.field_mask = ParamsUpdate::kLimits;
  update.omega_max = 1.0;
  update.c_min = 3.0;
  update.c_max = 15.0;
  update.seq = 1;
  EXPECT_EQ(controller.applyParams(update), ParamsOutcome::kApplied);
  ASSERT_TRUE(controller.onStateEstimate(estimateAt(200000, far), tick));
  EXPECT_NEAR(tick.command.body_rate.norm(), 1.0, 1e-9);
  EXPECT_TRUE(tick.command.saturated & 1);

  update.omega_max = -1.0;  // invalid: ignored as a whole
  update.seq = 2;
  EXPECT_EQ(controller.applyParams(update), ParamsOutcome::kInvalid);
  ASSERT_TRUE(controller.onStateEstimate(estimateAt(300000, far), tick));
  EXPECT_NEAR(tick.command.body_rate.norm(), 1.0, 1e-9);
  EXPECT_EQ(tick.reference.params_seq, 1);  // the refused update is not named
}

TEST(StateDependentLqr, WeightsWithoutAStabilizingGainAreRefusedAtConstruction) {
  LqrParams lqr;
  lqr.r_diag[0] = -1.0;  // invalid
  EXPECT_THROW(StateDependentLqr(lqr, ControllerParams{}), std::runtime_error);
}

}  // namespace
}  // namespace sdlqr::controller
