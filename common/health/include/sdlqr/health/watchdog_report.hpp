#pragma once
// A stream watchdog's state in HEARTBEAT: counters watchdog.<stream>.expired (0/1),
// .timeouts (entries into silence) and .age_ms (since the last valid message; -1 before one).

#include <cmath>
#include <string>

#include "sdlqr/health/counters.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/math/same_bits.hpp"

namespace sdlqr {

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
    counters_.set(age_ms_, dog.started() ? roundToInt64(1e3 * dog.age(now_s)) : -1);
  }

 private:
  Counters& counters_;
  Counters::Id expired_;
  Counters::Id timeouts_;
  Counters::Id age_ms_;
};

// A stream watchdog fed with wall time and reported in the counters: what every core's
// onWallTime() runs for each stream whose silence it must notice.
class StreamWatchdog {
 public:
  StreamWatchdog(Counters& counters, const std::string& stream, double timeout_s)
      : dog_(timeout_s), report_(counters, stream) {}
  void feed(double now_s) { dog_.feed(now_s); }
  // Checks and reports; true while the stream is silent past its timeout.
  bool check(double now_s) {
    const bool silent = dog_.check(now_s);
    report_.update(dog_, now_s);
    return silent;
  }
  const Watchdog& watchdog() const { return dog_; }

 private:
  Watchdog dog_;
  WatchdogReport report_;
};

}  // namespace sdlqr
