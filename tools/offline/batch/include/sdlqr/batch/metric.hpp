#pragma once
// A number of a flight's report that a table carries besides its criteria (batch rows, compare
// tables), and the worst of a value over a flight's windows.

#include <algorithm>
#include <cmath>
#include <limits>

#include "sdlqr/analysis/flight_report.hpp"

namespace sdlqr::batch {

struct Metric {
  const char* name;
  const char* unit;
  double (*of)(const analysis::FlightReport&);
};

// The largest `of(item)` over `items`; NaN when there are none, +inf when one was never reached
// (NaN): a window that never settled is worse than any that did.
template <class Container, class Of>
double largestOf(const Container& items, Of of) {
  double worst = std::numeric_limits<double>::quiet_NaN();
  for (const auto& item : items) {
    const double v = of(item);
    if (std::isnan(v)) return std::numeric_limits<double>::infinity();
    worst = std::isnan(worst) ? v : std::max(worst, v);
  }
  return worst;
}

}  // namespace sdlqr::batch
