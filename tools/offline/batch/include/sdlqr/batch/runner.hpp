#pragma once
// Flies a batch (or its shard) on `jobs` threads, each flight on its own ClosedLoop: flights share
// nothing but the loaded nominal configuration, so the rows do not depend on which thread flew
// what or in which order (flights.csv is sorted). Each row is journaled as it lands; a run in a
// folder holding part of the same batch flies only what is missing.

#include <string>

#include "sdlqr/batch/results.hpp"

namespace sdlqr::batch {

struct RunOptions {
  std::string out_dir;
  int jobs = 1;
  Shard shard;
  bool terminal = false;   // progress redrawn in place
  bool progress = true;
};

struct RunResult {
  long long resumed = 0;   // rows found in the journal
  long long flown = 0;     // rows flown by this run
  double wall_s = 0.0;
  double simulated_s = 0.0;  // simulation time flown by this run
  Table table;             // every row of the shard, sorted
};

// Throws ConfigError (a draw that is no valid plant) or std::runtime_error (the folder).
RunResult runBatch(const BatchContext& context, const RunOptions& options);

}  // namespace sdlqr::batch
