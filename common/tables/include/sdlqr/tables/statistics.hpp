#pragma once
// Summary statistics of a sample, as metrics.json reports them.

#include <cstdint>
#include <vector>

namespace sdlqr::tables {

struct Distribution {
  int64_t count = 0;
  double mean = 0.0;  // all fields NaN when count == 0 (metrics.json: null)
  double min = 0.0;
  double median = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

// Percentiles interpolate linearly between the closest ranks (numpy.percentile's default), so
// a Python cross-check of an exported CSV gives the same figures.
Distribution describe(std::vector<double> values);

// p in [0, 100]; `sorted` ascending and not empty.
double percentileOfSorted(const std::vector<double>& sorted, double p);

}  // namespace sdlqr::tables
