#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sdlqr/math/lqr_params.hpp"

#include "config_errors.hpp"

namespace sdlqr {
namespace {

LqrParams loadText(const std::string& text) { return testing::loadSectionText<LqrParams>(text, "lqr"); }

TEST(LqrParams, DefaultsAreThePapersAndValid) {
  const LqrParams p;
  EXPECT_TRUE(p.valid()) << p.invalidReason();
  EXPECT_EQ(p.q_diag[0], 100.0);
  EXPECT_EQ(p.q_diag[3], 1.0);
  EXPECT_EQ(p.q_diag[9], 10.0);
  EXPECT_EQ(p.r_diag[3], 0.1);
  EXPECT_EQ(p.omega_max, 2.0);
  EXPECT_EQ(p.c_min, 2.0);
  EXPECT_EQ(p.c_max, 18.0);
  EXPECT_EQ(p.dt, 0.01);
}

TEST(LqrParams, LoadsEveryKey) {
  const LqrParams p = loadText(
      "{q_diag: [1,2,3,4,5,6,7,8,9,10], r_diag: [1,2,3,4], dt: 0.02, omega_max: 3, c_min: 1, c_max: 20,"
      " gravity: 9.8, method: iterative, tolerance: 1e-10, max_iterations: 50}");
  EXPECT_EQ(p.q_diag[9], 10.0);
  EXPECT_EQ(p.r_diag[2], 3.0);
  EXPECT_EQ(p.dt, 0.02);
  EXPECT_EQ(p.method, LqrMethod::kIterative);
  EXPECT_EQ(p.max_iterations, 50);
}

TEST(LqrParams, EveryInvalidFieldNamesItsKey) {
  testing::expectKeysBlamed(loadText, {
      {"{r_diag: [1, 0, 1, 1]}", "lqr.r_diag[1]"},
      {"{r_diag: [1, -5, 1, 1]}", "lqr.r_diag[1]"},
      {"{r_diag: [1, 1, 1]}", "lqr.r_diag"},
      {"{q_diag: [1,1,1,1,1,1,1,1,1,-1]}", "lqr.q_diag[9]"},
      {"{q_diag: [1,1,1,1,1,1,1,1,1,.nan]}", "lqr.q_diag[9]"},
      {"{dt: 0}", "lqr.dt"},
      {"{dt: fast}", "lqr.dt"},
      {"{c_min: 10, c_max: 5}", "lqr.c_max"},
      {"{omega_max: -1}", "lqr.omega_max"},
      {"{method: newton}", "lqr.method"},
      {"{q_diagg: [1]}", "lqr.q_diagg"},
      {"{tolerance: 2}", "lqr.tolerance"},
  });
}

TEST(LqrParams, InvalidReasonCatchesProgrammaticChanges) {
  LqrParams p;
  p.r_diag[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(p.valid());
  p = LqrParams();
  p.gravity = 0.0;
  EXPECT_FALSE(p.valid());
}

// RuntimeLqrParams::apply: the one rule of the gain solver and the controller for PARAMS.
ParamsUpdate updateAt(int64_t utime, int64_t seq, int32_t mask) {
  ParamsUpdate u;
  u.utime = utime;
  u.seq = seq;
  u.field_mask = mask;
  u.q_diag = LqrParams().q_diag * 2.0;
  u.r_diag = LqrParams().r_diag * 3.0;
  u.omega_max = 1.5;
  u.c_min = 3.0;
  u.c_max = 15.0;
  u.mass = 0.3;
  u.tracking = ReferenceMode::kTemporal;
  return u;
}

bool sameParams(const LqrParams& a, const LqrParams& b) {
  return a.q_diag == b.q_diag && a.r_diag == b.r_diag && a.omega_max == b.omega_max && a.c_min == b.c_min &&
         a.c_max == b.c_max && a.dt == b.dt && a.gravity == b.gravity && a.method == b.method;
}

TEST(RuntimeLqrParams, WeightsBitSetsQAndROnly) {
  RuntimeLqrParams lqr{LqrParams()};
  const ParamsUpdate u = updateAt(100, 1, ParamsUpdate::kWeights);
  ASSERT_EQ(lqr.apply(u), ParamsOutcome::kApplied);
  EXPECT_EQ(lqr.params().q_diag, u.q_diag);
  EXPECT_EQ(lqr.params().r_diag, u.r_diag);
  EXPECT_EQ(lqr.params().omega_max, LqrParams().omega_max);
  EXPECT_EQ(lqr.params().c_max, LqrParams().c_max);
  EXPECT_EQ(lqr.seq(), 1);
}

TEST(RuntimeLqrParams, LimitsBitSetsOmegaAndThrustBoundsOnly) {
  RuntimeLqrParams lqr{LqrParams()};
  const ParamsUpdate u = updateAt(100, 1, ParamsUpdate::kLimits);
  ASSERT_EQ(lqr.apply(u), ParamsOutcome::kApplied);
  EXPECT_EQ(lqr.params().omega_max, 1.5);
  EXPECT_EQ(lqr.params().c_min, 3.0);
  EXPECT_EQ(lqr.params().c_max, 15.0);
  EXPECT_EQ(lqr.params().q_diag, LqrParams().q_diag);
}

TEST(RuntimeLqrParams, MassAndTrackingBitsChangeNoLqrParameterButCountAsApplied) {
  for (int32_t mask : {ParamsUpdate::kMass, ParamsUpdate::kTracking, ParamsUpdate::kMass | ParamsUpdate::kTracking}) {
    RuntimeLqrParams lqr{LqrParams()};
    ASSERT_EQ(lqr.apply(updateAt(100, 7, mask)), ParamsOutcome::kApplied) << "mask " << mask;
    EXPECT_TRUE(sameParams(lqr.params(), LqrParams())) << "mask " << mask;
    EXPECT_EQ(lqr.seq(), 7) << "mask " << mask;
  }
}

TEST(RuntimeLqrParams, ARefusedUpdateLeavesEverythingUnchanged) {
  RuntimeLqrParams lqr{LqrParams()};
  ASSERT_EQ(lqr.apply(updateAt(100, 1, ParamsUpdate::kLimits)), ParamsOutcome::kApplied);
  const LqrParams before = lqr.params();
  ParamsUpdate bad_r = updateAt(200, 2, ParamsUpdate::kWeights | ParamsUpdate::kLimits);
  bad_r.r_diag[2] = 0.0;  // R not positive definite: the valid limits in the same update are refused too
  ParamsUpdate bad_limits = updateAt(200, 3, ParamsUpdate::kLimits);
  bad_limits.c_max = bad_limits.c_min;
  ParamsUpdate bad_mass = updateAt(200, 4, ParamsUpdate::kWeights | ParamsUpdate::kMass);
  bad_mass.mass = -1.0;
  ParamsUpdate bad_tracking = updateAt(200, 5, ParamsUpdate::kWeights | ParamsUpdate::kTracking);
  bad_tracking.tracking = static_cast<ReferenceMode>(9);
  const ParamsUpdate unknown_bit = updateAt(200, 6, ParamsUpdate::kWeights | 64);
  for (const ParamsUpdate& bad : {bad_r, bad_limits, bad_mass, bad_tracking, unknown_bit}) {
    EXPECT_EQ(lqr.apply(bad), ParamsOutcome::kInvalid) << "seq " << bad.seq;
    EXPECT_TRUE(sameParams(lqr.params(), before)) << "seq " << bad.seq;
    EXPECT_EQ(lqr.seq(), 1) << "seq " << bad.seq;
  }
  // Guards the loop above: the same update without its fault is applied.
  ParamsUpdate good = bad_r;
  good.r_diag = LqrParams().r_diag;
  EXPECT_EQ(lqr.apply(good), ParamsOutcome::kApplied);
  EXPECT_FALSE(sameParams(lqr.params(), before));
}

TEST(RuntimeLqrParams, AnUpdateNotAfterTheLastAppliedOneIsNotNewer) {
  RuntimeLqrParams lqr{LqrParams()};
  ASSERT_EQ(lqr.apply(updateAt(1000, 5, ParamsUpdate::kLimits)), ParamsOutcome::kApplied);
  const LqrParams applied = lqr.params();
  ParamsUpdate weights = updateAt(1000, 5, ParamsUpdate::kWeights);  // a re-send: same utime and seq
  EXPECT_EQ(lqr.apply(weights), ParamsOutcome::kNotNewer);
  weights.seq = 4;  // older seq at the same time
  EXPECT_EQ(lqr.apply(weights), ParamsOutcome::kNotNewer);
  weights = updateAt(999, 9, ParamsUpdate::kWeights);  // newer seq, older time: a reordered packet
  EXPECT_EQ(lqr.apply(weights), ParamsOutcome::kNotNewer);
  EXPECT_TRUE(sameParams(lqr.params(), applied));
  EXPECT_EQ(lqr.seq(), 5);
  // A restarted mission counts seq from 0 again; its later time makes the update newer.
  EXPECT_EQ(lqr.apply(updateAt(2000, 0, ParamsUpdate::kWeights)), ParamsOutcome::kApplied);
  EXPECT_EQ(lqr.seq(), 0);
}

TEST(RuntimeLqrParams, ARefusedUpdateDoesNotBlockALaterOneWithTheSameSeq) {
  RuntimeLqrParams lqr{LqrParams()};
  ParamsUpdate bad = updateAt(100, 1, ParamsUpdate::kLimits);
  bad.omega_max = -1.0;
  ASSERT_EQ(lqr.apply(bad), ParamsOutcome::kInvalid);
  EXPECT_EQ(lqr.apply(updateAt(100, 1, ParamsUpdate::kLimits)), ParamsOutcome::kApplied);
}

}  // namespace
}  // namespace sdlqr
