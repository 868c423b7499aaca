#pragma once
// The opt-in real-time mode of a flight process (scripts/launch --realtime): the launcher gives
// each process its SCHED_FIFO priority (chrt) and asks, through SDLQR_REALTIME=1 in the
// environment, that the process lock its memory — which only the process itself can do.

#include <string>

namespace sdlqr::bus {

// With SDLQR_REALTIME=1: mlockall(MCL_CURRENT | MCL_FUTURE), so no page of the process is ever
// paged out or faulted in late. Returns the one-line reason when that is not permitted (the
// caller prints it and runs on), empty when locked or not asked.
std::string lockMemoryWhenAsked();

}  // namespace sdlqr::bus
