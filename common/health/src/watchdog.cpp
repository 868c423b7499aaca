#include "sdlqr/health/watchdog.hpp"

namespace sdlqr {

bool Watchdog::check(double now_s) {
  const bool silent = started() && now_s - last_feed_s_ > timeout_s_;
  if (silent && !expired_) ++timeouts_;
  expired_ = silent;
  return expired_;
}

FaultParams::FaultParams() { declaration().setDefaults(*this); }

const ParamTable<FaultParams>& FaultParams::declaration() {
  static const ParamTable<FaultParams> table = [] {
    using P = FaultParams;
    ParamTable<P> t("watchdogs and the STATE_EST clock gate");
    t.number("controller_state_timeout", &P::controller_state_timeout_s, 0.05, "s", Range::openClosed(0.0, 10.0),
             "wall time without a valid STATE_EST: controller FAILSAFE in HEARTBEAT");
    t.number("lowlevel_imu_timeout", &P::lowlevel_imu_timeout_s, 0.02, "s", Range::openClosed(0.0, 10.0),
             "wall time without a valid IMU sample: lowlevel FAILSAFE in HEARTBEAT");
    t.number("state_max_jump", &P::state_max_jump_s, 0.5, "s", Range::openClosed(0.0, 60.0),
             "larger forward jumps of STATE_EST time need confirming");
    t.integer("state_jump_confirmations", &P::state_jump_confirmations, 5, "-", Range::closed(1, 1000),
              "consecutive consistent estimates that confirm such a jump");
    return t;
  }();
  return table;
}

}  // namespace sdlqr
