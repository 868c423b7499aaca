// The gain solver process logic: 10 Hz in simulation time, linearized at the estimate and the
// controller's reference input, run-time parameter updates.

#include <gtest/gtest.h>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/gains/gain_scheduler.hpp"
#include "sdlqr/gains/gains_params.hpp"

#include "config_errors.hpp"

namespace sdlqr::gains {
namespace {

StateEstimate estimateAt(int64_t utime) {
  StateEstimate e;
  e.utime = utime;
  e.seq = utime / 4000;
  e.position = Vec3(0.5, -0.2, 1.0);
  e.orientation = quat::exp(Vec3(0.3, -0.2, 1.0));
  e.velocity = Vec3(1.0, 0.5, -0.2);
  e.status = EstimatorStatus::kOk;
  return e;
}

TEST(GainScheduler, DueOnceEvery100MsOfSimulationTime) {
  GainScheduler scheduler(LqrParams{}, 10.0);
  int due = 0;
  for (int64_t utime = 0; utime < 2000000; utime += 4000) due += scheduler.due(estimateAt(utime)) ? 1 : 0;
  EXPECT_EQ(due, 20);
}

TEST(GainScheduler, LinearizesAtTheEstimateAndTheReferenceInput) {
  const LqrParams lqr;
  GainScheduler scheduler(lqr, 10.0);
  Reference reference;
  reference.u = makeInput(Vec3(0.5, -0.3, 0.2), 12.0);
  scheduler.setReference(reference);
  const StateEstimate estimate = estimateAt(400000);
  GainSet out;
  ASSERT_EQ(scheduler.solve(estimate, out), SolveStatus::kOk);
  const LqrResult direct = solveLqr(estimate.state(), reference.u, lqr);
  EXPECT_EQ(out.K, direct.K);
  EXPECT_EQ(out.u_lin, reference.u);
  EXPECT_EQ(out.state_seq, estimate.seq);
  EXPECT_EQ(out.utime, estimate.utime);
  EXPECT_EQ(out.q_diag, lqr.q_diag);
  EXPECT_EQ(out.params_seq, -1);
  EXPECT_NEAR(orientation(out.x_lin).norm(), 1.0, 1e-15);
}

TEST(GainScheduler, ParamsChangeTheNextSolveAndInvalidOnesAreRefused) {
  GainScheduler scheduler(LqrParams{}, 10.0);
  GainSet before, after;
  ASSERT_EQ(scheduler.solve(estimateAt(0), before), SolveStatus::kOk);
  ParamsUpdate update;
  update.seq = 3;
  update.field_mask = ParamsUpdate::kWeights;
  update.q_diag = LqrParams{}.q_diag * 4.0;
  update.r_diag = LqrParams{}.r_diag;
  ASSERT_EQ(scheduler.applyParams(update), ParamsOutcome::kApplied);
  ASSERT_EQ(scheduler.solve(estimateAt(100000), after), SolveStatus::kOk);
  EXPECT_EQ(after.params_seq, 3);
  EXPECT_EQ(after.q_diag, update.q_diag);
  EXPECT_GT((after.K - before.K).norm(), 1e-3);

  ParamsUpdate bad = update;
  bad.seq = 4;
  bad.q_diag = LqrParams{}.q_diag;
  bad.r_diag[3] = 0.0;  // R not positive definite
  EXPECT_EQ(scheduler.applyParams(bad), ParamsOutcome::kInvalid);
  EXPECT_EQ(scheduler.params().q_diag, update.q_diag);
  EXPECT_EQ(scheduler.params().r_diag, LqrParams{}.r_diag);
  GainSet refused;
  ASSERT_EQ(scheduler.solve(estimateAt(200000), refused), SolveStatus::kOk);
  EXPECT_EQ(refused.params_seq, 3);  // the refused update is not named
}

TEST(GainScheduler, FailedSolveLeavesKZeroAndCounts) {
  GainScheduler scheduler(LqrParams{}, 10.0);
  StateEstimate broken = estimateAt(0);
  broken.orientation = Quat::Zero();
  GainSet out;
  EXPECT_EQ(scheduler.solve(broken, out), SolveStatus::kInvalidInput);
  EXPECT_TRUE(out.K.isZero());
  EXPECT_EQ(scheduler.failures(), 1);
}

TEST(ControllerConfig, EveryInvalidFieldNamesItsKey) {
  const auto key_of = [](const std::string& text, auto loader) {
    return testing::keyBlamedBy([&] { loader(ConfigReader(YAML::Load(text), "section")); });
  };
  const auto controller = [](const ConfigReader& r) { controller::ControllerParams::load(r); };
  const auto gains = [](const ConfigReader& r) { GainsParams::load(r); };
  EXPECT_EQ(key_of("{rate_hz: 0}", controller), "section.rate_hz");
  EXPECT_EQ(key_of("{gains_stale_s: 2, gains_fallback_s: 1}", controller), "section.gains_fallback_s");
  EXPECT_EQ(key_of("{tracking: sideways}", controller), "section.tracking");
  EXPECT_EQ(key_of("{landing_speed: -1}", controller), "section.landing_speed");
  EXPECT_EQ(key_of("{rate_hzz: 100}", controller), "section.rate_hzz");
  EXPECT_EQ(key_of("{rate_hz: .nan}", gains), "section.rate_hz");
  EXPECT_EQ(key_of("{state_timeout_s: 0}", gains), "section.state_timeout_s");
  EXPECT_EQ(key_of("{}", controller), "<no error>");
}

}  // namespace
}  // namespace sdlqr::gains
