#include "sdlqr/health/watchdog.hpp"

#include "watchdog_rows.hpp"

namespace sdlqr {

bool Watchdog::check(double now_s) {
  const bool silent = started() && now_s - last_feed_s_ > timeout_s_;
  if (silent && !expired_) ++timeouts_;
  expired_ = silent;
  return expired_;
}

FaultParams::FaultParams() { declaration().setDefaults(*this); }

const ParamTable<FaultParams>& FaultParams::declaration() {
  static const ParamTable<FaultParams> table = faultParamsRows();
  return table;
}

}  // namespace sdlqr
