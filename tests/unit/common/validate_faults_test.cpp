// The receiver-side checks added for a hostile bus: the closed-loop check of a received K, the
// clock gate of the STATE_EST stream, stream watchdogs and the `faults:` parameters.

#include <gtest/gtest.h>

#include <iostream>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"

namespace sdlqr {
namespace {

GainSet solvedAt(const State& x, const Input& u) {
  LqrParams params;
  const LqrResult result = solveLqr(x, u, params);
  EXPECT_EQ(result.status, SolveStatus::kOk);
  GainSet g;
  g.K = result.K;
  g.x_lin = x;
  g.u_lin = u;
  g.q_diag = params.q_diag;
  g.r_diag = params.r_diag;
  g.dt = params.dt;
  return g;
}

State hoverState() {
  State x = State::Zero();
  x[kQuat] = 1.0;
  x[2] = 1.0;
  return x;
}

Input hoverInput() { return (Input() << 0.0, 0.0, 0.0, kDefaultGravity).finished(); }

TEST(ClosedLoopCheck, SolvedGainsPassAtHoverAndInAManoeuvre) {
  const GainSet hover = solvedAt(hoverState(), hoverInput());
  State tilted = hoverState();
  orientation(tilted) = Quat(0.9, 0.3, -0.2, 0.25).normalized();
  velocity(tilted) = Vec3(3.0, -1.0, 0.5);
  const GainSet manoeuvre = solvedAt(tilted, (Input() << 1.5, -1.0, 0.8, 14.0).finished());
  std::cout << "closed-loop spectral radius: hover " << closedLoopSpectralRadius(hover) << ", manoeuvre "
            << closedLoopSpectralRadius(manoeuvre) << "\n";
  EXPECT_EQ(validateClosedLoop(hover), RejectReason::kNone);
  EXPECT_EQ(validateClosedLoop(manoeuvre), RejectReason::kNone);
}

TEST(ClosedLoopCheck, ForgedGainsWithPlausibleEntriesAreUnstable) {
  const GainSet good = solvedAt(hoverState(), hoverInput());
  GainSet flipped = good;
  flipped.K = -good.K;  // positive feedback, every entry in range
  GainSet zero = good;
  zero.K.setZero();  // open loop: the position modes are integrators (|lambda| = 1)
  GainSet scaled = good;
  scaled.K *= 60.0;  // overshoots every discrete pole
  std::cout << "spectral radius: -K " << closedLoopSpectralRadius(flipped) << ", K=0 "
            << closedLoopSpectralRadius(zero) << ", 60 K " << closedLoopSpectralRadius(scaled) << "\n";
  EXPECT_EQ(validate(flipped, ValidationLimits{}), RejectReason::kNone);  // in range: only the closed loop tells
  EXPECT_EQ(validateClosedLoop(flipped), RejectReason::kUnstable);
  EXPECT_EQ(validateClosedLoop(zero), RejectReason::kUnstable);
  EXPECT_EQ(validateClosedLoop(scaled), RejectReason::kUnstable);
  GainSet bad_quaternion = good;
  orientation(bad_quaternion.x_lin).setZero();
  EXPECT_EQ(validateClosedLoop(bad_quaternion), RejectReason::kUnstable);
  EXPECT_STREQ(counterName(RejectReason::kUnstable), "reject.unstable");
}

TEST(ClockGate, RejectsBackwardsAndUnconfirmedJumps) {
  ClockGate gate(500'000, 3);
  EXPECT_EQ(gate.offer(1'000'000), RejectReason::kNone);
  EXPECT_EQ(gate.offer(1'004'000), RejectReason::kNone);
  EXPECT_EQ(gate.offer(1'004'000), RejectReason::kTimeBackwards);  // a replay of the same time
  EXPECT_EQ(gate.offer(10), RejectReason::kTimeBackwards);
  EXPECT_EQ(gate.offer(9'000'000'000'000), RejectReason::kTimeFuture);  // one forged future message
  EXPECT_EQ(gate.offer(1'008'000), RejectReason::kNone);                  // the real stream goes on
  EXPECT_EQ(gate.now(), 1'008'000);
}

TEST(ClockGate, ARestartedPublisherAfterALongGapIsFollowedOnceConfirmed) {
  ClockGate gate(500'000, 3);
  EXPECT_EQ(gate.offer(1'000'000), RejectReason::kNone);
  EXPECT_EQ(gate.offer(6'000'000), RejectReason::kTimeFuture);  // 5 s later: the estimator restarted
  EXPECT_EQ(gate.offer(6'004'000), RejectReason::kTimeFuture);
  EXPECT_EQ(gate.offer(6'008'000), RejectReason::kNone);
  EXPECT_EQ(gate.now(), 6'008'000);
  EXPECT_EQ(gate.offer(6'012'000), RejectReason::kNone);
}

TEST(ClockGate, ScatteredForgedTimesNeverConfirmEachOther) {
  ClockGate gate(500'000, 3);
  gate.offer(1'000'000);
  int64_t forged = 50'000'000;
  int64_t real = 1'000'000;
  for (int i = 0; i < 100; ++i) {
    forged += (i % 2 == 0 ? 1 : -1) * 7'000'000 * (i + 1);  // far apart, alternating direction
    if (forged > real + 500'000) {
      EXPECT_EQ(gate.offer(forged), RejectReason::kTimeFuture);
    }
    real += 4000;
    EXPECT_EQ(gate.offer(real), RejectReason::kNone);
  }
}

TEST(Watchdog, ExpiresAfterTheTimeoutAndCountsEachSilenceOnce) {
  Watchdog dog(0.1);
  EXPECT_FALSE(dog.check(5.0));  // not started
  EXPECT_DOUBLE_EQ(dog.age(5.0), -1.0);
  dog.feed(1.0);
  EXPECT_FALSE(dog.check(1.09));
  EXPECT_TRUE(dog.check(1.1001));
  EXPECT_TRUE(dog.check(2.0));
  EXPECT_EQ(dog.timeouts(), 1);
  dog.feed(2.0);
  EXPECT_FALSE(dog.check(2.05));
  EXPECT_TRUE(dog.check(3.0));
  EXPECT_EQ(dog.timeouts(), 2);
  EXPECT_NEAR(dog.age(3.0), 1.0, 1e-12);
}

TEST(FaultParams, DefaultsAreValidAndEachBadKeyIsNamed) {
  EXPECT_TRUE(FaultParams{}.valid());
  const char* keys[] = {"controller_state_timeout", "lowlevel_imu_timeout", "state_max_jump",
                        "state_jump_confirmations"};
  for (const char* key : keys) {
    YAML::Node node(YAML::NodeType::Map);
    node[key] = std::string(key) == "state_jump_confirmations" ? "0" : "-1.0";
    try {
      FaultParams::load(ConfigReader(node, "faults"));
      ADD_FAILURE() << key << " accepted";
    } catch (const ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("faults.") + key), std::string::npos) << e.what();
    }
  }
  YAML::Node unknown(YAML::NodeType::Map);
  unknown["imu_timeout"] = 0.1;
  EXPECT_THROW(FaultParams::load(ConfigReader(unknown, "faults")), ConfigError);
}

}  // namespace
}  // namespace sdlqr
