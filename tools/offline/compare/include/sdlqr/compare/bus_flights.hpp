#pragma once
// The files that fly a benchmark's experiments over the bus, one folder per controller and
// experiment (`./sdlqr compare --bus`): the in-process comparison's subset flown by the real
// processes, each law with the same scenario, seed and criteria.
//
//   DIR/<controller>/<experiment>/vehicle.yaml   the experiment's vehicle file with lqr.law: controller
//   DIR/<controller>/<experiment>/scenario.yaml  the experiment with vehicle: that file (and the
//                                                benchmark's seed, when it sets one)
//   DIR/plan.txt                                 one line per flight: controller experiment folder

#include <string>

#include "sdlqr/compare/benchmark.hpp"

namespace sdlqr::compare {

// Writes the folders and plan.txt (DIR created); returns the number of flights. Throws
// ConfigError naming the experiment when its files cannot be read or written.
int writeBusFlights(const Benchmark& benchmark, const std::string& dir);

}  // namespace sdlqr::compare
