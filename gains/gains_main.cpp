// sdlqr-gains: the state-dependent LQR gain solver. Bus mode (default): at 10 Hz of simulation
// time, linearize at the newest STATE_EST and the controller's reference input, solve, publish
// GAINS. One-shot mode (--once): solve at the given point and print one JSON object.

#include <chrono>
#include <iostream>
#include <stdexcept>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/gains/gain_scheduler.hpp"
#include "sdlqr/gains/gains_cli.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/watchdog_report.hpp"

namespace {

using namespace sdlqr;

int runOnBus(const ProcessOptions& options, const LqrParams& lqr, const gains::GainsParams& params,
             const FaultParams& faults, const ValidationLimits& limits) {
  gains::GainScheduler scheduler(lqr, params.rate_hz);
  bus::Node bus("sdlqr-gains", options);
  bus::Counters::Id reject_ids[static_cast<int>(RejectReason::kCount)];
  for (int i = 0; i < static_cast<int>(RejectReason::kCount); ++i) {
    reject_ids[i] = bus.counters().add(counterName(static_cast<RejectReason>(i)));
  }
  const auto params_refused_id = bus.counters().add("reject.params_invalid");
  const auto solves_id = bus.counters().add("gains.solves");
  const auto failures_id = bus.counters().add("gains.failures");
  auto reject = [&](RejectReason reason) {
    if (reason == RejectReason::kNone) return false;
    bus.countRejected(reject_ids[static_cast<int>(reason)]);
    return true;
  };
  ClockGate state_time(static_cast<int64_t>(faults.state_max_jump_s * 1e6), faults.state_jump_confirmations);
  Watchdog state_watchdog(params.state_timeout_s);
  bus::WatchdogReport state_report(bus.counters(), "state_est");

  GainSet gains;
  // A solve that outlasts the estimate period makes the next estimate wait (the 10 Hz schedule
  // itself has 100 ms of room).
  constexpr std::chrono::microseconds kSolveBudget{4000};
  bus.subscribe<state_estimate_t>(channel::kStateEstimate, [&](const state_estimate_t& msg) {
    const StateEstimate estimate = bus::fromLcm(msg);
    RejectReason reason = validate(estimate, limits);
    if (reason == RejectReason::kNone) reason = state_time.offer(estimate.utime);
    if (reject(reason)) return;
    bus.setSimTime(estimate.utime);
    state_watchdog.feed(bus::monotonicSeconds());
    if (estimate.status == EstimatorStatus::kInitializing || !scheduler.due(estimate)) return;
    const auto start = std::chrono::steady_clock::now();
    const SolveStatus status = scheduler.solve(estimate, gains);
    gains.solve_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count();
    bus.counters().increment(solves_id);
    if (status != SolveStatus::kOk) {
      // DESIGN §7: nothing is published, the controller keeps its last K.
      bus.counters().increment(failures_id);
      bus.countError();
      bus.setLastError("solve failed at STATE_EST seq " + std::to_string(estimate.seq) + ": status " +
                       std::to_string(static_cast<int>(status)));
      return;
    }
    bus.publish(channel::kGains, bus::toLcm(gains));
  }, 1, kSolveBudget);
  bus.subscribe<reference_t>(channel::kReference, [&](const reference_t& msg) {
    const Reference reference = bus::fromLcm(msg);
    if (reject(validate(reference, limits))) return;
    scheduler.setReference(reference);
  });
  bus.subscribe<params_t>(channel::kParams, [&](const params_t& msg) {
    const ParamsUpdate update = bus::fromLcm(msg);
    if (reject(validate(update, limits))) return;
    const ParamsOutcome outcome = scheduler.applyParams(update);
    if (outcome == ParamsOutcome::kNotNewer) {
      bus.countRejected(reject_ids[static_cast<int>(RejectReason::kTimeBackwards)]);
    } else if (outcome == ParamsOutcome::kInvalid) {
      bus.countRejected(params_refused_id);
      bus.setLastError("PARAMS seq " + std::to_string(update.seq) + " refused: the weights or limits are invalid");
    }
  }, 16);

  std::cerr << "sdlqr-gains: solving at " << params.rate_hz << " Hz on " << bus.channel(channel::kStateEstimate)
            << " (" << toString(lqr.method) << " method)\n";
  while (bus.spin(20)) {
    const double now = bus::monotonicSeconds();
    const bool silent = state_watchdog.check(now);
    bus.setState(!state_watchdog.started() ? bus::ProcessState::kStarting
                 : silent                  ? bus::ProcessState::kDegraded
                                           : bus::ProcessState::kRunning);
    state_report.update(state_watchdog, now);
  }
  bus.shutdown();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-gains", [&] {
    bool once = false;
    std::string state_text, input_text, method_text;
    ProcessOptions options;
    ArgParser parser("sdlqr-gains", "State-dependent LQR gain solver (paper §II-C, II-D).");
    parser.addFlag("--once", &once, "solve once at --state/--input, print one JSON object and exit\n"
                   "                          (without it: solve at 10 Hz on the bus and publish GAINS)");
    parser.addOption("--state", &state_text, "P3,Q4,V3", "linearization state px,py,pz,qw,qx,qy,qz,vx,vy,vz");
    parser.addOption("--input", &input_text, "W3,C", "linearization input wx,wy,wz,c (rad/s, m/s^2)");
    parser.addOption("--method", &method_text, "NAME", "tangent or iterative (default: lqr.method of --config)");
    addProcessOptions(parser, &options);
    parser.setEpilog(
        "example: sdlqr-gains --once --state 0,0,1,1,0,0,0,0,0,0 --input 0,0,0,9.81\n"
        "output:  {\"status\", \"method\", \"K\" (4x10, u = u0 + K (x - x0)), \"dt\", \"iterations\",\n"
        "          \"solve_us\", \"residual\", \"x_lin\" (quaternion normalized), \"u_lin\"}\n"
        "exit codes: 0 solved, 1 solver failure (JSON still printed), 2 bad input or config");
    parser.parseOrExit(argc, argv);
    const ConfigReader config = loadVehicleConfig(options.config_path);
    LqrParams params = LqrParams::load(config.child("lqr"));
    if (!method_text.empty() && !parseLqrMethod(method_text, params.method)) {
      throw std::invalid_argument("--method: expected tangent or iterative, got '" + method_text + "'");
    }
    if (!once) {
      if (!state_text.empty() || !input_text.empty()) throw std::invalid_argument("--state and --input need --once");
      const gains::GainsParams gains_params = gains::GainsParams::load(config.child("gains"));
      const FaultParams faults = FaultParams::load(config.child("faults"));
      const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
      if (options.print_config) {
        printProcessConfig(std::cout, "sdlqr-gains", options.config_path,
                           {printedSection("lqr", params), printedSection("gains", gains_params),
                            printedSection("faults", faults), printedSection("validation", limits)});
        return 0;
      }
      return runOnBus(options, params, gains_params, faults, limits);
    }
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-gains --once", options.config_path, {printedSection("lqr", params)});
      return 0;
    }
    if (state_text.empty() || input_text.empty()) throw std::invalid_argument("--once needs --state and --input");

    State x = gains::parseStateList(state_text, "--state");
    const Input u = gains::parseInputList(input_text, "--input");

    const auto start = std::chrono::steady_clock::now();
    const LqrResult result = solveLqr(x, u, params);
    const auto stop = std::chrono::steady_clock::now();
    orientation(x).normalize();
    const double solve_us = std::chrono::duration<double, std::micro>(stop - start).count();
    std::cout << gains::formatGainsJson(x, u, params, result, solve_us) << "\n";
    return result.status == SolveStatus::kOk ? 0 : 1;
  });
}
