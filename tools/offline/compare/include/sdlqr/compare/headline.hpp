#pragma once
// The comparison's headline (issue 25): per vehicle and law, the fastest speed each sweep flew
// within its criteria and the path error there, the experiments passed, and where the paper's law
// wins or loses against the hover LQR and the geometric cascade. Several benchmarks of one vehicle
// (a circle sweep in one, a lemniscate sweep in another) share its rows.

#include <string>
#include <vector>

#include "sdlqr/compare/benchmark.hpp"
#include "sdlqr/compare/compare_run.hpp"

namespace sdlqr::compare {

struct HeadlineRun {
  const Benchmark* benchmark;
  const CompareResult* result;
};

// "## Headline" with its table and the paper's law against the others, per vehicle.
std::string headlineMarkdown(const std::vector<HeadlineRun>& runs);

}  // namespace sdlqr::compare
