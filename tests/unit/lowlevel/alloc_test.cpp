// step() of the bodyrate loop allocates nothing, in every mode: global operator new/delete are
// replaced by counting versions in this binary only.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "flight_harness.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace sdlqr::test {
namespace {

TEST(BodyrateLoopAllocation, StepAllocatesNothingInAnyMode) {
  FlightHarness h;
  h.plant.startHovering(3.0);
  long during_steps = 0;
  auto counted = [&](auto&& body) {
    const long before = g_allocations.load();
    body();
    during_steps += g_allocations.load() - before;
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
