// sdlqr-controller: wires the bus to the 100 Hz state-dependent LQR (controller/ library).

#include <algorithm>
#include <chrono>
#include <iostream>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/controller/state_dependent_lqr.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/watchdog_report.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  return runMain("sdlqr-controller", [&] {
    ProcessOptions options;
    ArgParser parser("sdlqr-controller",
                     "State-dependent LQR at 100 Hz of simulation time: u = u0 + K (x - x0) with the newest\n"
                     "GAINS, the paper's input limits and a setpoint or trajectory reference.\n"
                     "In: STATE_EST, GAINS, TRAJECTORY, PARAMS, COMMAND.  Out: RATE_CMD, REFERENCE, HEARTBEAT.");
    addProcessOptions(parser, &options);
    parser.setEpilog("exit codes: 0 stopped by SIGINT/SIGTERM, 1 runtime failure, 2 bad option or configuration");
    parser.parseOrExit(argc, argv);

    const ConfigReader config = loadVehicleConfig(options.config_path);
    const LqrParams lqr = LqrParams::load(config.child("lqr"));
    const controller::ControllerParams params = controller::ControllerParams::load(config.child("controller"));
    const FaultParams faults = FaultParams::load(config.child("faults"));
    const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
    throwIfInvalid(config.child("lqr"), lqrLimitsInvalidReason(lqr, limits));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-controller", options.config_path,
                         {printedSection("lqr", lqr), printedSection("controller", params),
                          printedSection("faults", faults), printedSection("validation", limits)});
      return 0;
    }
    controller::StateDependentLqr lqr_controller(lqr, params);

    bus::Node bus("sdlqr-controller", options);
    bus::Counters::Id reject_ids[static_cast<int>(RejectReason::kCount)];
    for (int i = 0; i < static_cast<int>(RejectReason::kCount); ++i) {
      reject_ids[i] = bus.counters().add(counterName(static_cast<RejectReason>(i)));
    }
    const auto ticks_id = bus.counters().add("controller.ticks");
    const auto fallback_id = bus.counters().add("controller.fallback_ticks");
    const auto stale_id = bus.counters().add("controller.stale_ticks");
    const auto saturated_id = bus.counters().add("controller.saturated_ticks");
    const auto trajectory_refused_id = bus.counters().add("reject.trajectory_refused");
    const auto params_refused_id = bus.counters().add("reject.params_invalid");
    // GAINS age is judged in simulation time by the library (stale, then the hover K); the
    // STATE_EST watchdog runs on wall time, since a silent estimator brings no time at all.
    const auto gains_freshness_id = bus.counters().add("watchdog.gains.freshness");  // 0 fresh, 1 stale, 2 fallback
    Watchdog state_watchdog(faults.controller_state_timeout_s);
    bus::WatchdogReport state_report(bus.counters(), "state_est");
    // Counts a rejection; true when the message must be dropped.
    auto reject = [&](RejectReason reason) {
      if (reason == RejectReason::kNone) return false;
      bus.countRejected(reject_ids[static_cast<int>(reason)]);
      return true;
    };
    ClockGate state_time(static_cast<int64_t>(faults.state_max_jump_s * 1e6), faults.state_jump_confirmations);
    TimeGate gains_time;
    OrderGate command_order, params_order;
    int64_t now_utime = -1;

    controller::StateDependentLqr::Tick tick;
    // A tick that takes longer than the estimate period delays the next estimate's tick.
    constexpr std::chrono::microseconds kTickBudget{4000};
    bus.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& msg) {
      const StateEstimate estimate = bus::fromLcm(msg);
      RejectReason reason = validate(estimate, limits);
      if (reason == RejectReason::kNone) reason = state_time.offer(estimate.utime);
      if (reject(reason)) return;
      state_watchdog.feed(bus::monotonicSeconds());
      now_utime = estimate.utime;
      bus.setSimTime(now_utime);
      if (!lqr_controller.onStateEstimate(estimate, tick)) return;
      bus.publish(channel::kRateCommand, bus::toLcm(tick.command));
      bus.publish(channel::kReference, bus::toLcm(tick.reference));
      const controller::ControllerStatus& status = lqr_controller.status();
      bus.counters().increment(ticks_id);
      bus.counters().set(gains_freshness_id, static_cast<int64_t>(status.gains));
      if (status.gains == GainsFreshness::kFallback) bus.counters().increment(fallback_id);
      if (status.gains == GainsFreshness::kStale) bus.counters().increment(stale_id);
      if (tick.command.saturated) bus.counters().increment(saturated_id);
      bus.setState(status.gains == GainsFreshness::kFresh ? bus::ProcessState::kRunning
                                                          : bus::ProcessState::kDegraded);
    }, 1, kTickBudget);
    bus.subscribe<gains_t>(channel::kGains, [&](const gains_t& msg) {
      const GainSet gains = bus::fromLcm(msg);
      RejectReason reason = validate(gains, limits);
      if (reason == RejectReason::kNone) reason = gains_time.check(gains.utime, now_utime);
      // Last: the eigenvalues cost ~10 us, spent only on a K that passed the cheap checks.
      if (reason == RejectReason::kNone) reason = validateClosedLoop(gains);
      if (reject(reason)) return;
      gains_time.accept(gains.utime);
      lqr_controller.setGains(gains);
    }, 4);
    bus.subscribe<command_t>(channel::kCommand, [&](const command_t& msg) {
      const Command command = bus::fromLcm(msg);
      RejectReason reason = validate(command, limits);
      if (reason == RejectReason::kNone) reason = command_order.offer(command.utime, command.seq, now_utime);
      if (reject(reason)) return;
      lqr_controller.handleCommand(command);
    }, 16);
    bus.subscribe<trajectory_t>(channel::kTrajectory, [&](const trajectory_t& msg) {
      const Trajectory trajectory = bus::fromLcm(msg);
      if (reject(validate(trajectory, limits))) return;
      const std::string refused = lqr_controller.setTrajectory(trajectory);
      if (!refused.empty()) {
        bus.countRejected(trajectory_refused_id);
        bus.setLastError("TRAJECTORY seq " + std::to_string(trajectory.seq) + " refused: " + refused);
      }
    }, 2);
    bus.subscribe<params_t>(channel::kParams, [&](const params_t& msg) {
      const ParamsUpdate update = bus::fromLcm(msg);
      RejectReason reason = validate(update, limits);
      if (reason == RejectReason::kNone) reason = params_order.offer(update.utime, update.seq, now_utime);
      if (reject(reason)) return;
      const ParamsOutcome outcome = lqr_controller.applyParams(update);
      if (outcome == ParamsOutcome::kInvalid) {
        bus.countRejected(params_refused_id);
        bus.setLastError("PARAMS seq " + std::to_string(update.seq) + " refused: the LQR parameters refuse it");
      }
    }, 16);

    std::cerr << "sdlqr-controller: running on " << bus.channel(channel::kStateEstimate) << "\n";
    // Short spins: the watchdog must notice a silent estimator within its timeout.
    const int spin_ms = std::max(1, static_cast<int>(faults.controller_state_timeout_s * 1e3 / 4));
    while (bus.spin(spin_ms)) {
      const double now = bus::monotonicSeconds();
      if (state_watchdog.check(now)) {
        // No estimate: nothing is commanded (the lowlevel's RATE_CMD timeout takes over).
        bus.setState(bus::ProcessState::kFailsafe);
      }
      state_report.update(state_watchdog, now);
    }
    bus.shutdown();
    return 0;
  });
}
