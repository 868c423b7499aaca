// sdlqr-mission re-sends its current pull (DISTURBANCE) with the same seq and a fresh utime, so
// that one lost datagram does not lose the pull: the simulator applies a pull once, whatever
// arrives again, and a new seq is a new pull.
#include <gtest/gtest.h>

#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/sim/sim_core.hpp"
#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

// A vehicle falling freely from 20 m, motors off: a pull of exactly its weight upwards holds its
// vertical speed; applied twice it would climb at 1 g.
class ResentPull : public ::testing::Test {
 protected:
  ResentPull() : core_(vehicle_, fallingFrom(20.0)) {}

  static SimParams fallingFrom(double height) {
    SimParams p = test::idealParams();
    p.initial_position = Vec3(0.0, 0.0, height);
    return p;
  }
  Disturbance lift(int64_t seq, int64_t utime, int64_t start_utime) const {
    Disturbance d;
    d.seq = seq;
    d.utime = utime;
    d.start_utime = start_utime;
    d.force = Vec3(0.0, 0.0, vehicle_.mass * kDefaultGravity);
    d.duration = 2.0;
    return d;
  }
  void runFor(double seconds) {
    for (int64_t i = std::llround(seconds / core_.simulator().period()); i > 0; --i) core_.step(bus_);
  }
  double verticalSpeed() const { return core_.simulator().body().velocity.z(); }
  int64_t accepted() const {
    const Counters& counters = core_.health().counters();
    return counters.value(counters.find("disturbance.accepted"));
  }

  VehicleParams vehicle_;
  SimCore core_;
  OutboxTo<NoObserver> bus_{NoObserver{}};
};

TEST_F(ResentPull, AReSentPullIsAppliedOnce) {
  ASSERT_EQ(core_.onDisturbance(lift(0, 0, 0)), RejectReason::kNone);
  runFor(0.1);
  ASSERT_EQ(core_.onDisturbance(lift(0, 100'000, 0)), RejectReason::kNone) << "a re-send is no fault";
  runFor(0.5);
  EXPECT_NEAR(verticalSpeed(), 0.0, 0.05) << "the lift applied twice climbs at 1 g";
  EXPECT_EQ(accepted(), 1);
}

TEST_F(ResentPull, AReSentPullWhoseFirstCopyWasLostIsApplied) {
  runFor(0.1);
  ASSERT_EQ(core_.onDisturbance(lift(0, 100'000, 0)), RejectReason::kNone);
  const double falling = verticalSpeed();
  runFor(0.5);
  EXPECT_NEAR(verticalSpeed(), falling, 0.05) << "held from its arrival";
  EXPECT_EQ(accepted(), 1);
}

TEST_F(ResentPull, ANewSeqIsANewPull) {
  ASSERT_EQ(core_.onDisturbance(lift(0, 0, 0)), RejectReason::kNone);
  ASSERT_EQ(core_.onDisturbance(lift(1, 1, 0)), RejectReason::kNone);
  runFor(0.5);
  EXPECT_NEAR(verticalSpeed(), 0.5 * kDefaultGravity, 0.05) << "two pulls of its weight: 1 g up";
  EXPECT_EQ(accepted(), 2);
}

}  // namespace
}  // namespace sdlqr::sim
