#pragma once
// The batch summary: per controller the flights that passed every check, with a Wilson score
// interval (95 %), the same per criterion, and the worst flights with the commands that fly one
// of them again alone (in-process) and over the bus with a log.

#include <string>

#include "sdlqr/batch/results.hpp"

namespace sdlqr::batch {

struct Interval {
  double low = 0.0;
  double high = 0.0;
};
// Wilson score interval of `passed` successes in `total` trials at z (1.96: 95 %); [0, 1] for total 0.
Interval wilson(long long passed, long long total, double z = 1.959963984540054);

std::string summaryText(const BatchContext& context, const Table& table);

// The flights to look at first: failed ones, most failed checks first, then the largest tilt.
std::vector<size_t> worstRows(const Table& table, size_t count);

}  // namespace sdlqr::batch
