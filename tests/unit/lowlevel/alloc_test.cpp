// step() of the bodyrate loop allocates nothing, in every mode (counted by the replaced operator
// new of tests/support).

#include <gtest/gtest.h>


#include "allocation_counter.hpp"
#include "flight_harness.hpp"

namespace sdlqr::test {
namespace {

TEST(BodyrateLoopAllocation, StepAllocatesNothingInAnyMode) {
  FlightHarness h;
  h.plant.startHovering(3.0);
  long during_steps = 0;
  auto counted = [&](auto&& body) {
    const long before = sdlqr::testing::allocationCount();
    body();
    during_steps += sdlqr::testing::allocationCount() - before;
  };
  counted([&] { h.tick(); });                                   // disarmed
  h.command(CommandType::kArm);
  counted([&] { for (int i = 0; i < 100; ++i) h.tick(); });     // idle
  for (int i = 0; i < 1000; ++i) {                              // rate
    if (i % 10 == 0) counted([&] { h.loop.setRateCommand(holdPosition(h.plant, Vec3(0, 0, 3), h.utime)); });
    counted([&] { h.tick(); });
  }
  ASSERT_EQ(h.loop.mode(), MotorMode::kRate);
  counted([&] { for (int i = 0; i < 8000 && h.loop.mode() != MotorMode::kDisarmed; ++i) h.tick(); });  // failsafe
  EXPECT_EQ(h.loop.mode(), MotorMode::kDisarmed);
  EXPECT_EQ(h.loop.counters().failsafe_entries, 1);
  EXPECT_EQ(during_steps, 0);
}

}  // namespace
}  // namespace sdlqr::test
