#pragma once
// From a min-snap polynomial to the sampled Trajectory the controller tracks (the paper samples
// at dt = 0.1 s): each sample holds the flat reference state and feed-forward input.

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/flatness.hpp"
#include "sdlqr/trajectory/min_snap.hpp"

namespace sdlqr::trajectory {

// Samples at t = 0, dt, 2 dt, ... and at the final time (the last interval may be shorter).
// Quaternions are kept in one hemisphere from sample to sample. A periodic polynomial gives a
// closed trajectory whose final sample closes the lap. Throws std::invalid_argument on dt <= 0.
Trajectory sampleTrajectory(const MinSnapTrajectory& polynomial, double dt, double gravity);

// Appends the flat reference of time t as a sample, its quaternion in the hemisphere of the last.
void appendSample(Trajectory& out, double t, const FlatReference& reference);

}  // namespace sdlqr::trajectory
