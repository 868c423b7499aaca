#pragma once
// The gain solver process, bus-free: validation and gates of its inputs, the STATE_EST watchdog
// (wall time), the counters and the 10 Hz scheduler. One method per input message, each returning
// the rejection (kNone: accepted). sdlqr-gains binds the bus to it; the replay and the in-process
// loop drive the same object.
//
//   STATE_EST  validate, ClockGate, then on the 10 Hz grid solve -> GAINS through the Outbox
//              (a failed solve publishes nothing: the controller keeps its last K)
//   REFERENCE  validate (its input u0 is the linearization input)
//   PARAMS     validate, OrderGate (a replayed one is refused), then the scheduler may refuse
//              weights or limits that make the parameters invalid (kRefused)
// No allocation on the STATE_EST path.

#include "sdlqr/gains/gain_scheduler.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/health/watchdog_report.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"

namespace sdlqr::gains {

class GainsCore {
 public:
  // A wall clock [s] to time each solve with (GAINS solve_us); nullptr: not timed (solve_us 0),
  // as in the in-process loop and the replay, whose outputs must not depend on the machine.
  using SolveClock = double (*)();

  GainsCore(const LqrParams& lqr, const GainsParams& params, const FaultParams& faults,
            const ValidationLimits& limits = {}, SolveClock solve_clock = nullptr);

  RejectReason onStateEstimate(const StateEstimate& estimate, Outbox& out);
  RejectReason onReference(const Reference& reference);
  RejectReason onParams(const ParamsUpdate& update);
  // Wall time [s]: STARTING before the first estimate, DEGRADED while STATE_EST is silent.
  void onWallTime(double now_s);

  // Ports (sdlqr/messages/ports.hpp). A solve that outlasts the estimate period makes the next
  // estimate wait (the 10 Hz schedule itself has 100 ms of room).
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&GainsCore::onStateEstimate, 1, std::chrono::microseconds(4000)},
        ports::Input{&GainsCore::onReference},
        ports::Input{&GainsCore::onParams, 16},
    };
  }
  using Outputs = ports::Publishes<GainSet>;

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const GainScheduler& scheduler() const { return scheduler_; }

 private:
  GainScheduler scheduler_;
  ValidationLimits limits_;
  SolveClock solve_clock_;
  ProcessHealth health_;
  ClockGate state_clock_;
  OrderGate params_order_;
  StreamWatchdog state_watchdog_;
  double wall_now_s_ = 0.0;
  GainSet gains_;
  Counters::Id solves_, failures_;
};

}  // namespace sdlqr::gains
