#pragma once
// Plays a scenario's events against simulation time (taken from IMU utime, DESIGN §2).

#include <cstddef>

#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::mission {

class MissionPlayer {
 public:
  explicit MissionPlayer(const Scenario& scenario) : scenario_(scenario) {}

  // Returns the next event due at or before `utime`, or nullptr; call until nullptr.
  const ScenarioEvent* nextDue(int64_t utime) {
    if (next_ >= scenario_.events.size()) return nullptr;
    const ScenarioEvent& event = scenario_.events[next_];
    if (static_cast<double>(utime) * 1e-6 < event.at) return nullptr;
    ++next_;
    return &event;
  }
  bool finished(int64_t utime) const { return static_cast<double>(utime) * 1e-6 >= scenario_.duration; }
  std::size_t played() const { return next_; }

 private:
  const Scenario& scenario_;
  std::size_t next_ = 0;
};

}  // namespace sdlqr::mission
