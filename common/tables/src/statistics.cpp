#include "sdlqr/tables/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sdlqr::tables {

double percentileOfSorted(const std::vector<double>& sorted, double p) {
  const double rank = p / 100.0 * static_cast<double>(sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(rank));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  const double fraction = rank - static_cast<double>(below);
  return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

Distribution describe(std::vector<double> values) {
  Distribution d;
  d.count = static_cast<int64_t>(values.size());
  if (values.empty()) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    d.mean = d.min = d.median = d.p99 = d.max = nan;
    return d;
  }
  std::sort(values.begin(), values.end());
  double sum = 0.0;
  for (double v : values) sum += v;
  d.mean = sum / static_cast<double>(values.size());
  d.min = values.front();
  d.max = values.back();
  d.median = percentileOfSorted(values, 50.0);
  d.p99 = percentileOfSorted(values, 99.0);
  return d;
}

}  // namespace sdlqr::tables
