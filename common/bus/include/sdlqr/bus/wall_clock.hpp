#pragma once
// The wall clock a main feeds its core's onWallTime(): what a silent stream is measured against.

#include <cstdint>
#include <ctime>

namespace sdlqr::bus {

// Seconds of the process's monotonic wall clock.
double monotonicSeconds();

// Microseconds since the Unix epoch (CLOCK_REALTIME): the instant a tool stamps what it reports,
// comparable with `date +%s%6N`.
inline int64_t realtimeUtime() {
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  return static_cast<int64_t>(now.tv_sec) * 1'000'000 + now.tv_nsec / 1000;
}

}  // namespace sdlqr::bus
