#pragma once
// The controller process, bus-free: validation and gates of every input, the STATE_EST watchdog
// (wall time), the counters and the state-dependent LQR. One method per input message; each
// returns the rejection (kNone: accepted). sdlqr-controller binds the bus to it, the replay and
// the in-process loop drive the same object, so a message is refused the same way in all three.
//
//   STATE_EST  validate, ClockGate (a forged far-future estimate cannot move the clock), tick
//              -> RATE_CMD + REFERENCE through the Outbox
//   GAINS      validate, TimeGate against the clock, the receiver's own closed-loop check of K
//   COMMAND, PARAMS  validate, OrderGate (a replayed one is refused)
//   TRAJECTORY validate, then the controller may refuse it (kRefused, with the reason in the
//              last error)
// No allocation on the STATE_EST and GAINS paths.

#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/controller/state_dependent_lqr.hpp"
#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/health/watchdog_report.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"

namespace sdlqr::controller {

class ControllerCore {
 public:
  ControllerCore(const LqrParams& lqr, const ControllerParams& params, const FaultParams& faults,
                 const ValidationLimits& limits = {});

  RejectReason onStateEstimate(const StateEstimate& estimate, Outbox& out);
  RejectReason onGains(const GainSet& gains);
  RejectReason onCommand(const Command& command);
  RejectReason onTrajectory(const Trajectory& trajectory);
  RejectReason onParams(const ParamsUpdate& update);
  // Wall time [s] (simulation time in the in-process loop and the replay): checks the STATE_EST
  // watchdog; a silent estimator means FAILSAFE (nothing is commanded, the lowlevel's RATE_CMD
  // timeout takes over).
  void onWallTime(double now_s);

  // Ports (sdlqr/messages/ports.hpp). A tick that takes longer than the estimate period delays
  // the next estimate's tick.
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&ControllerCore::onStateEstimate, 1, std::chrono::microseconds(4000)},
        ports::Input{&ControllerCore::onGains, 4},
        ports::Input{&ControllerCore::onCommand, 16},
        ports::Input{&ControllerCore::onTrajectory, 2},
        ports::Input{&ControllerCore::onParams, 16},
    };
  }
  using Outputs = ports::Publishes<RateCommand, Reference>;

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const StateDependentLqr& lqr() const { return lqr_; }
  // How often the bus main must call onWallTime() for the watchdog to notice within its timeout.
  int wallTimePeriodMs() const;

 private:
  void countTick(const RateCommand& command);

  StateDependentLqr lqr_;
  FaultParams faults_;
  ValidationLimits limits_;
  ProcessHealth health_;
  ClockGate state_clock_;
  TimeGate gains_time_;
  OrderGate command_order_, params_order_;
  StreamWatchdog state_watchdog_;
  double wall_now_s_ = 0.0;
  StateDependentLqr::Tick tick_;
  Counters::Id ticks_, fallback_ticks_, stale_ticks_, saturated_ticks_, gains_freshness_, guard_aborts_,
      transitions_, entries_refused_, trajectories_scaled_;
};

}  // namespace sdlqr::controller
