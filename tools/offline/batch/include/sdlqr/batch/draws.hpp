#pragma once
// Flight k's parameter values and noise seed, from the batch seed and k alone: a flight draws the
// same whatever flew before it, on whichever thread, shard or machine (splitmix64 streams and
// hand-written uniform and normal transforms: no standard-library distribution whose output
// differs between implementations).

#include <cstdint>
#include <vector>

#include "sdlqr/batch/spec.hpp"

namespace sdlqr::batch {

struct FlightDraw {
  int flight = 0;
  long long seed = 0;           // the simulator's noise seed
  std::vector<double> values;   // one per spec parameter, as the flight sets it (relative: applied)
};

// `nominal` and `stress` (the scenario's `sim:` stressors) give relative parameters their nominal.
FlightDraw drawFlight(const BatchSpec& spec, const closedloop::StackConfig& nominal, const sim::SimStress& stress,
                      int flight);

// Flights of shard `index` (1-based) of `count`: k with k mod count == index - 1.
bool inShard(int flight, int index, int count);

}  // namespace sdlqr::batch
