#pragma once
// A stream watchdog's state in HEARTBEAT: counters watchdog.<stream>.expired (0/1),
// .timeouts (entries into silence) and .age_ms (since the last valid message; -1 before one).

#include <cmath>
#include <string>

#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/bus/node.hpp"

namespace sdlqr::bus {

class WatchdogReport {
 public:
  WatchdogReport(Counters& counters, const std::string& stream)
      : counters_(counters),
        expired_(counters.add("watchdog." + stream + ".expired")),
        timeouts_(counters.add("watchdog." + stream + ".timeouts")),
        age_ms_(counters.add("watchdog." + stream + ".age_ms")) {}

  void update(const Watchdog& dog, double now_s) {
    counters_.set(expired_, dog.expired() ? 1 : 0);
    counters_.set(timeouts_, dog.timeouts());
    counters_.set(age_ms_, dog.started() ? static_cast<int64_t>(std::llround(1e3 * dog.age(now_s))) : -1);
  }

 private:
  Counters& counters_;
  Counters::Id expired_;
  Counters::Id timeouts_;
  Counters::Id age_ms_;
};

// Seconds of the process's monotonic wall clock: what a silent stream is measured against.
double monotonicSeconds();

}  // namespace sdlqr::bus
