#include "sdlqr/controller/controller_core.hpp"

#include <algorithm>
#include <string>

namespace sdlqr::controller {

ControllerCore::ControllerCore(const LqrParams& lqr, const ControllerParams& params, const FaultParams& faults,
                               const ValidationLimits& limits)
    : lqr_(lqr, params),
      faults_(faults),
      limits_(limits),
      state_clock_(static_cast<int64_t>(faults.state_max_jump_s * 1e6), faults.state_jump_confirmations),
      // GAINS age is judged in simulation time by the library (stale, then the hover K); the
      // STATE_EST watchdog runs on wall time, since a silent estimator brings no time at all.
      state_watchdog_(health_.counters(), "state_est", faults.controller_state_timeout_s),
      ticks_(health_.counters().add("controller.ticks")),
      fallback_ticks_(health_.counters().add("controller.fallback_ticks")),
      stale_ticks_(health_.counters().add("controller.stale_ticks")),
      saturated_ticks_(health_.counters().add("controller.saturated_ticks")),
      gains_freshness_(health_.counters().add("watchdog.gains.freshness")),  // 0 fresh, 1 stale, 2 fallback
      guard_aborts_(health_.counters().add("trajectory.guard_abort")),
      transitions_(health_.counters().add("trajectory.transitions")),
      entries_refused_(health_.counters().add("trajectory.entry_refused")),
      trajectories_scaled_(health_.counters().add("trajectory.scaled")) {}

RejectReason ControllerCore::onStateEstimate(const StateEstimate& estimate, Outbox& out) {
  const RejectReason reason = admitClock(estimate, limits_, state_clock_);
  if (health_.reject(Stream::kStateEstimate, reason)) return reason;
  state_watchdog_.feed(wall_now_s_);
  health_.setSimTime(estimate.utime);
  if (!lqr_.onStateEstimate(estimate, tick_)) return RejectReason::kNone;
  out.publish(tick_.command);
  out.publish(tick_.reference);
  countTick(tick_.command);
  return RejectReason::kNone;
}

void ControllerCore::countTick(const RateCommand& command) {
  const ControllerStatus& status = lqr_.status();
  Counters& c = health_.counters();
  c.increment(ticks_);
  c.set(gains_freshness_, static_cast<int64_t>(status.gains));
  if (status.gains == GainsFreshness::kFallback) c.increment(fallback_ticks_);
  if (status.gains == GainsFreshness::kStale) c.increment(stale_ticks_);
  if (command.saturated) c.increment(saturated_ticks_);
  c.set(guard_aborts_, lqr_.references().guardAborts());
  c.set(transitions_, lqr_.references().transitions());
  c.set(entries_refused_, lqr_.references().entriesRefused());
  health_.setState(status.gains == GainsFreshness::kFresh ? ProcessState::kRunning : ProcessState::kDegraded);
}

RejectReason ControllerCore::onGains(const GainSet& gains) {
  RejectReason reason = validate(gains, limits_);
  if (reason == RejectReason::kNone) reason = gains_time_.check(gains.utime, state_clock_.now());
  // Last: the eigenvalues cost ~10 us, spent only on a K that passed the cheap checks.
  if (reason == RejectReason::kNone) reason = validateClosedLoop(gains, lqr_.modelRotorDrag());
  if (health_.reject(Stream::kGains, reason)) return reason;
  gains_time_.accept(gains.utime);
  lqr_.setGains(gains);
  return RejectReason::kNone;
}

RejectReason ControllerCore::onCommand(const Command& command) {
  return health_.admit(Stream::kCommand, admitOrdered(command, limits_, command_order_, state_clock_.now()),
                       [&] { lqr_.handleCommand(command); });
}

RejectReason ControllerCore::onTrajectory(const Trajectory& trajectory) {
  const RejectReason reason = validate(trajectory, limits_);
  if (health_.reject(Stream::kTrajectory, reason)) return reason;
  const int64_t scaled_before = lqr_.references().trajectoriesScaled();
  const std::string refused = lqr_.setTrajectory(trajectory);
  if (refused.empty()) {
    const ReferenceGenerator& references = lqr_.references();
    health_.counters().set(trajectories_scaled_, references.trajectoriesScaled());
    if (references.trajectoriesScaled() != scaled_before) {  // accepted, but slower than sent: say so
      health_.setLastError("TRAJECTORY seq " + std::to_string(trajectory.seq) + " flown time-scaled: " +
                           references.lastScaling());
    }
    return RejectReason::kNone;
  }
  health_.reject(Stream::kTrajectory, RejectReason::kRefused);
  health_.setLastError("TRAJECTORY seq " + std::to_string(trajectory.seq) + " refused: " + refused);
  return RejectReason::kRefused;
}

RejectReason ControllerCore::onParams(const ParamsUpdate& update) {
  RejectReason reason = admitOrdered(update, limits_, params_order_, state_clock_.now());
  if (reason == RejectReason::kNone) reason = rejectionOf(lqr_.applyParams(update));
  if (reason == RejectReason::kRefused) {
    health_.setLastError("PARAMS seq " + std::to_string(update.seq) + " refused: the LQR parameters refuse it");
  }
  health_.reject(Stream::kParams, reason);
  return reason;
}

void ControllerCore::onWallTime(double now_s) {
  wall_now_s_ = now_s;
  if (state_watchdog_.check(now_s)) health_.setState(ProcessState::kFailsafe);
}

int ControllerCore::wallTimePeriodMs() const {
  return std::max(1, static_cast<int>(faults_.controller_state_timeout_s * 1e3 / 4));
}

}  // namespace sdlqr::controller
