#pragma once
// Plays a scenario's events against simulation time (the utime of SIM_CLOCK, published by the
// simulator every 10 ms). Times are compared in whole microseconds: an event at 0.05 s is due at
// utime 50000 (in doubles, 50000 * 1e-6 < 0.05 and it would wait for the next tick).

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::mission {

class MissionPlayer {
 public:
  explicit MissionPlayer(const Scenario& scenario) : scenario_(scenario) {}

  // Returns the next event due at or before `utime`, or nullptr; call until nullptr.
  const ScenarioEvent* nextDue(int64_t utime) {
    if (next_ >= scenario_.events.size()) return nullptr;
    const ScenarioEvent& event = scenario_.events[next_];
    if (utime < toUtime(event.at)) return nullptr;
    ++next_;
    return &event;
  }
  bool finished(int64_t utime) const { return utime >= toUtime(scenario_.duration); }
  std::size_t played() const { return next_; }

 private:
  static int64_t toUtime(double seconds) { return static_cast<int64_t>(std::llround(seconds * 1e6)); }
  const Scenario& scenario_;
  std::size_t next_ = 0;
};

}  // namespace sdlqr::mission
