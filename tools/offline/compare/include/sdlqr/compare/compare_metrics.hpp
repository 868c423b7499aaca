#pragma once
// The columns of a comparison table: numbers of a flight's report where lower is better (errors,
// times, counts, height lost), declared once. A value of NaN means the metric does not apply to
// the flight (no jump, no trajectory, no recovery); +inf means it applies and was never reached
// (never settled, never level). Some come from the batch's flightMetrics(), the rest are the
// comparison's own.

#include <vector>

#include "sdlqr/batch/metric.hpp"

namespace sdlqr::compare {

const std::vector<batch::Metric>& compareMetrics();

}  // namespace sdlqr::compare
