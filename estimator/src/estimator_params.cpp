#include "sdlqr/estimator/estimator_params.hpp"

#include <cmath>

#include "estimator_params_rows.hpp"

namespace sdlqr::estimator {

int64_t EstimatorParams::outputPeriodUs() const { return static_cast<int64_t>(std::llround(1e6 / output_rate)); }

int EstimatorParams::historyCapacity() const {
  const double period = static_cast<double>(outputPeriodUs()) * 1e-6;
  // States at T, T - period, ..., back to T - history_length, plus the one just before it so a
  // capture time exactly history_length old still has a state at or before it.
  return static_cast<int>(std::ceil(history_length / period - 1e-9)) + 2;
}

EstimatorParams::EstimatorParams() { declaration().setDefaults(*this); }

const ParamTable<EstimatorParams>& EstimatorParams::declaration() {
  static const ParamTable<EstimatorParams> table = [] {
    using P = EstimatorParams;
    ParamTable<P> t = estimatorParamsRows();
    // Above accel_range a reading is rejected, so a higher clip level could never be seen.
    t.check("accel_clip_level", [](const P& p) { return p.accel_clip_level <= p.accel_range; }, "must be <= accel_range");
    t.check("output_rate",
            [](const P& p) {
              const double period_us = 1e6 / p.output_rate;
              return std::abs(period_us - std::round(period_us)) <= 1e-6;
            },
            "1e6 / output_rate must be a whole number of microseconds (e.g. 250, 200, 500)");
    t.check("history_length", [](const P& p) { return p.history_length * p.output_rate >= 2.0; },
            "must span at least two output periods");
    t.check("reinit_after", [](const P& p) { return p.reinit_after > p.vio_timeout; }, "must be > vio_timeout");
    // Past reinit_after the next pose re-initialises anyway; a reset must come before that.
    t.check("vio_reset_after", [](const P& p) { return p.vio_reset_after < p.reinit_after; }, "must be < reinit_after");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::estimator
