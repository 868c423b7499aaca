#include "sdlqr/gains/gains_core.hpp"

#include <string>

namespace sdlqr::gains {

GainsCore::GainsCore(const LqrParams& lqr, const GainsParams& params, const FaultParams& faults,
                     const ValidationLimits& limits, SolveClock solve_clock)
    : scheduler_(lqr, params.rate_hz),
      limits_(limits),
      solve_clock_(solve_clock),
      state_clock_(static_cast<int64_t>(faults.state_max_jump_s * 1e6), faults.state_jump_confirmations),
      state_watchdog_(health_.counters(), "state_est", params.state_timeout_s),
      solves_(health_.counters().add("gains.solves")),
      failures_(health_.counters().add("gains.failures")) {}

RejectReason GainsCore::onStateEstimate(const StateEstimate& estimate, Outbox& out) {
  const RejectReason reason = admitClock(estimate, limits_, state_clock_);
  if (health_.reject(Stream::kStateEstimate, reason)) return reason;
  health_.setSimTime(estimate.utime);
  state_watchdog_.feed(wall_now_s_);
  if (estimate.status == EstimatorStatus::kInitializing || !scheduler_.due(estimate)) return RejectReason::kNone;
  const double start = solve_clock_ ? solve_clock_() : 0.0;
  const SolveStatus status = scheduler_.solve(estimate, gains_);
  gains_.solve_us = solve_clock_ ? 1e6 * (solve_clock_() - start) : 0.0;
  health_.counters().increment(solves_);
  if (status != SolveStatus::kOk) {
    // Nothing is published: the controller keeps its last K.
    health_.counters().increment(failures_);
    health_.countError();
    health_.setLastError("solve failed at STATE_EST seq " + std::to_string(estimate.seq) + ": status " +
                         std::to_string(static_cast<int>(status)));
    return RejectReason::kNone;
  }
  out.publish(gains_);
  return RejectReason::kNone;
}

RejectReason GainsCore::onReference(const Reference& reference) {
  return health_.admit(Stream::kReference, validate(reference, limits_), [&] { scheduler_.setReference(reference); });
}

RejectReason GainsCore::onParams(const ParamsUpdate& update) {
  RejectReason reason = admitOrdered(update, limits_, params_order_, state_clock_.now());
  if (reason == RejectReason::kNone) reason = rejectionOf(scheduler_.applyParams(update));
  if (reason == RejectReason::kRefused) {
    health_.setLastError("PARAMS seq " + std::to_string(update.seq) + " refused: the weights or limits are invalid");
  }
  health_.reject(Stream::kParams, reason);
  return reason;
}

void GainsCore::onWallTime(double now_s) {
  wall_now_s_ = now_s;
  const bool silent = state_watchdog_.check(now_s);
  health_.setState(!state_watchdog_.watchdog().started() ? ProcessState::kStarting
                   : silent                              ? ProcessState::kDegraded
                                                         : ProcessState::kRunning);
}

}  // namespace sdlqr::gains
