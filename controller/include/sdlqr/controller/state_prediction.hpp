#pragma once
// Carries a state estimate a few milliseconds forward through the paper's model, eq. (3), with
// the estimated body rates and the thrust last commanded. The controller uses it to compute each
// command for its exact tick time from the last estimate before that tick, instead of ticking on
// whichever 250 Hz estimate comes first after it (which puts 2 ms of jitter on a 100 Hz period).

#include <cstdint>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr::controller {

// The estimate at `to_utime` (>= estimate.utime). One RK4 step: the horizons used (< 5 ms) are
// far below the attitude dynamics' time constants. Biases, covariances and seqs are kept.
StateEstimate predictEstimate(const StateEstimate& estimate, double thrust, int64_t to_utime, double gravity);

}  // namespace sdlqr::controller
