// The scenario player on SIM_CLOCK's 10 ms grid: an event given to the centisecond fires on the
// tick stamped with its own time, never the next one.

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "sdlqr/mission/mission_player.hpp"

namespace sdlqr::mission {
namespace {

constexpr int64_t kTickUs = 10000;  // SIM_CLOCK period

// The tick (utime) at which the player first returns the scenario's single event.
int64_t firingTick(const Scenario& scenario) {
  MissionPlayer player(scenario);
  for (int64_t utime = 0; utime <= 4000LL * 1000000; utime += kTickUs) {
    if (player.nextDue(utime) != nullptr) return utime;
  }
  return -1;
}

TEST(MissionPlayer, EveryCentisecondEventFiresOnItsOwnTick) {
  // GIVEN events at every multiple of 10 ms of the first hour, written as a scenario file would
  // hold them (decimal text parsed to double: 0.05 is not exactly representable)
  int late = 0;
  for (int64_t k = 0; k < 360000; k += 7) {  // a stride co-prime with 10 covers every last digit
    char text[32];
    std::snprintf(text, sizeof text, "%lld.%02lld", static_cast<long long>(k / 100), static_cast<long long>(k % 100));
    Scenario scenario;
    scenario.duration = 4000.0;
    ScenarioEvent event;
    event.at = std::stod(text);
    scenario.events.push_back(event);
    // WHEN the clock ticks every 10 ms THEN the event fires on the tick at its time
    MissionPlayer player(scenario);
    if (k > 0) {
      ASSERT_EQ(player.nextDue(k * kTickUs - kTickUs), nullptr) << text;
    }
    if (player.nextDue(k * kTickUs) == nullptr) ++late;
  }
  EXPECT_EQ(late, 0);
}

TEST(MissionPlayer, FiresOnceInOrderAndFinishesAtTheDuration) {
  Scenario scenario;
  scenario.duration = 0.05;
  for (double at : {0.01, 0.03, 0.03}) {
    ScenarioEvent event;
    event.at = at;
    scenario.events.push_back(event);
  }
  MissionPlayer player(scenario);
  EXPECT_EQ(player.nextDue(0), nullptr);
  EXPECT_EQ(player.nextDue(10000), &scenario.events[0]);
  EXPECT_EQ(player.nextDue(10000), nullptr);
  EXPECT_EQ(player.nextDue(30000), &scenario.events[1]);
  EXPECT_EQ(player.nextDue(30000), &scenario.events[2]);
  EXPECT_EQ(player.nextDue(30000), nullptr);
  EXPECT_FALSE(player.finished(40000));
  EXPECT_TRUE(player.finished(50000));
}

TEST(MissionPlayer, FiringTickOfAnEventBetweenTicksIsTheNextTick) {
  Scenario scenario;
  scenario.duration = 10.0;
  ScenarioEvent event;
  event.at = 0.0123;
  scenario.events.push_back(event);
  EXPECT_EQ(firingTick(scenario), 20000);
}

}  // namespace
}  // namespace sdlqr::mission
