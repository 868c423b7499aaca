#include <gtest/gtest.h>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/control_law.hpp"

namespace sdlqr::controller {
namespace {

GainMatrix hoverGain(const LqrParams& params) {
  const LqrResult r = solveLqr(makeState(Vec3::Zero(), identityQuat(), Vec3::Zero()),
                               makeInput(Vec3::Zero(), params.gravity), params);
  EXPECT_EQ(r.status, SolveStatus::kOk);
  return r.K;
}

TEST(ControlLaw, IsTheAffinePolicyOfEquation15InsideTheLimits) {
  const LqrParams params;
  const GainMatrix K = hoverGain(params);
  const State x_ref = makeState(Vec3(0, 0, 1), identityQuat(), Vec3::Zero());
  const Input u_ref = makeInput(Vec3::Zero(), params.gravity);
  const State x = makeState(Vec3(0.01, -0.02, 1.01), quat::exp(Vec3(0.01, 0.0, 0.0)), Vec3(0.01, 0, 0));
  const ControlOutput out = applyControlLaw(K, identityQuat(), x, x_ref, u_ref, params, ErrorBounds{});
  EXPECT_LT((out.u - (u_ref + K * (x - x_ref))).norm(), 1e-12);
  EXPECT_FALSE(out.rate_saturated);
  EXPECT_FALSE(out.thrust_saturated);
}

TEST(ControlLaw, QuaternionSignsDoNotChangeTheCommand) {
  // q, -q, -q_ref and a K built at -q_lin all describe the same situation.
  const LqrParams params;
  const State x_ref = makeState(Vec3(0, 0, 1), quat::fromYaw(0.3), Vec3::Zero());
  const Input u_ref = makeInput(Vec3::Zero(), params.gravity);
  const Quat q = quat::multiply(quat::fromYaw(0.3), quat::exp(Vec3(0.05, -0.02, 0.1)));
  const State x_lin = makeState(Vec3(0.1, 0, 1), q, Vec3(0.2, 0, 0));
  const LqrResult at_q = solveLqr(x_lin, u_ref, params);
  State x_lin_flipped = x_lin;
  orientation(x_lin_flipped) = -q;
  const LqrResult at_minus_q = solveLqr(x_lin_flipped, u_ref, params);
  ASSERT_EQ(at_q.status, SolveStatus::kOk);
  ASSERT_EQ(at_minus_q.status, SolveStatus::kOk);

  const State x = makeState(Vec3(0.1, 0, 1), quat::multiply(q, quat::exp(Vec3(0.01, 0.02, -0.01))), Vec3(0.2, 0, 0));
  const Input reference = applyControlLaw(at_q.K, q, x, x_ref, u_ref, params, ErrorBounds{}).u;
  for (const double sign_x : {1.0, -1.0}) {
    for (const double sign_ref : {1.0, -1.0}) {
      for (const bool flipped_gain : {false, true}) {
        State xs = x, refs = x_ref;
        orientation(xs) *= sign_x;
        orientation(refs) *= sign_ref;
        const GainMatrix& K = flipped_gain ? at_minus_q.K : at_q.K;
        const Quat q_lin = flipped_gain ? Quat(-q) : q;
        const Input u = applyControlLaw(K, q_lin, xs, refs, u_ref, params, ErrorBounds{}).u;
        EXPECT_LT((u - reference).norm(), 1e-9) << sign_x << " " << sign_ref << " " << flipped_gain;
      }
    }
  }
}

TEST(ControlLaw, BodyRateIsScaledToTheLimitKeepingItsDirection) {
  LqrParams params;
  params.omega_max = 2.0;
  GainMatrix K = GainMatrix::Zero();
  K(0, 0) = -10.0;  // roll rate from x error
  K(1, 1) = 10.0;   // pitch rate from y error
  const State x_ref = makeState(Vec3::Zero(), identityQuat(), Vec3::Zero());
  const State x = makeState(Vec3(0.3, 0.4, 0), identityQuat(), Vec3::Zero());
  const ControlOutput out = applyControlLaw(K, identityQuat(), x, x_ref, makeInput(Vec3::Zero(), 9.81), params, ErrorBounds{});
  EXPECT_TRUE(out.rate_saturated);
  EXPECT_NEAR(bodyRate(out.u).norm(), 2.0, 1e-12);
  EXPECT_NEAR(out.u[0] / out.u[1], -3.0 / 4.0, 1e-12);
}

TEST(ControlLaw, ThrustIsClippedToItsLimits) {
  const LqrParams params;
  GainMatrix K = GainMatrix::Zero();
  K(3, 2) = -100.0;
  const State x_ref = makeState(Vec3::Zero(), identityQuat(), Vec3::Zero());
  const Input u_ref = makeInput(Vec3::Zero(), 9.81);
  const ControlOutput low = applyControlLaw(K, identityQuat(), makeState(Vec3(0, 0, 0.5), identityQuat(), Vec3::Zero()), x_ref,
                                            u_ref, params, ErrorBounds{});
  const ControlOutput high = applyControlLaw(K, identityQuat(), makeState(Vec3(0, 0, -0.5), identityQuat(), Vec3::Zero()), x_ref,
                                             u_ref, params, ErrorBounds{});
  EXPECT_EQ(low.u[kThrust], params.c_min);
  EXPECT_EQ(high.u[kThrust], params.c_max);
  EXPECT_TRUE(low.thrust_saturated);
  EXPECT_TRUE(high.thrust_saturated);
}

TEST(ControlLaw, PositionAndVelocityErrorsAreBoundedInNorm) {
  const ErrorBounds bounds{1.0, 2.0};
  const State x_ref = makeState(Vec3::Zero(), identityQuat(), Vec3::Zero());
  const State x = makeState(Vec3(3.0, 4.0, 0.0), identityQuat(), Vec3(0.0, 0.0, -10.0));
  const State error = stateError(x, x_ref, identityQuat(), bounds);
  EXPECT_NEAR(position(error).norm(), 1.0, 1e-12);
  EXPECT_NEAR(error[0] / error[1], 0.75, 1e-12);
  EXPECT_NEAR(velocity(error)[2], -2.0, 1e-12);
  const State small = makeState(Vec3(0.3, 0.0, 0.0), identityQuat(), Vec3(0.5, 0, 0));
  EXPECT_LT((stateError(small, x_ref, identityQuat(), bounds) - (small - x_ref)).norm(), 1e-15);
}

}  // namespace
}  // namespace sdlqr::controller
