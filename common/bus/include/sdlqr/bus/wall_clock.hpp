#pragma once
// The wall clock a main feeds its core's onWallTime(): what a silent stream is measured against.

namespace sdlqr::bus {

// Seconds of the process's monotonic wall clock.
double monotonicSeconds();

}  // namespace sdlqr::bus
