#include "sdlqr/closedloop/closed_loop.hpp"

#include <cmath>

namespace sdlqr::closedloop {

namespace {

sim::SimParams withSeed(sim::SimParams params, long long seed) {
  params.seed = seed;
  return params;
}

mission::MissionOptions missionOptions(double command_resend_s) {
  mission::MissionOptions options;
  options.resend_interval_s = command_resend_s;
  return options;
}

}  // namespace

ClosedLoop::ClosedLoop(const StackConfig& config, const mission::Scenario& scenario, RecordOptions record,
                       double command_resend_s)
    : ClosedLoop(config, Plant{config.vehicle, config.sim}, scenario, record, command_resend_s) {}

ClosedLoop::ClosedLoop(const StackConfig& config, const Plant& plant, const mission::Scenario& scenario,
                       RecordOptions record, double command_resend_s)
    : recorder_{record, {}},
      duration_s_(scenario.duration),
      truth_rate_hz_(plant.sim.truth_rate_hz),
      imu_rate_hz_(plant.sim.imu.rate_hz),
      estimate_period_us_(config.estimator.outputPeriodUs()),
      sim_(plant.vehicle, withSeed(plant.sim, scenario.seed), scenario.sim),
      estimator_(config.estimator),
      lowlevel_(config.vehicle, config.lowlevel, config.lqr.gravity, config.faults, config.validation),
      controller_(config.lqr, config.controller, config.faults, config.validation),
      gains_(config.lqr, config.gains, config.faults, config.validation),
      mission_(scenario, config.trajectory, {config.lqr, config.controller.guard, config.controller.transition},
               missionOptions(command_resend_s)) {
  reserveRecording();
}

void ClosedLoop::reserveRecording() {
  const auto count = [this](double rate_hz) { return static_cast<size_t>(std::ceil(duration_s_ * rate_hz)) + 1; };
  recorder_.log.sim_truth.reserve(count(truth_rate_hz_));
  recorder_.log.state_estimate.reserve(count(1e6 / static_cast<double>(estimate_period_us_)));
  if (recorder_.options.imu) recorder_.log.imu.reserve(count(imu_rate_hz_));
  if (recorder_.options.motor_command) recorder_.log.motor_command.reserve(count(imu_rate_hz_));  // one per IMU sample
}

void ClosedLoop::recordInto(logger::FlightLog&& storage) {
  recorder_.log = std::move(storage);
  recorder_.log.clear();
  reserveRecording();
}

logger::FlightLog ClosedLoop::takeLog() {
  logger::FlightLog out = std::move(recorder_.log);
  recorder_.log = logger::FlightLog();
  return out;
}

// Wall time is simulation time: each core's watchdogs see the simulated pace.
bool ClosedLoop::step() {
  if (mission_.finished()) return false;
  wiring_.feedWallTime(1e-6 * static_cast<double>(utime()));
  sim_.step(wiring_.outboxOf<sim::SimCore>());
  return true;
}

void ClosedLoop::run() {
  while (step()) {
  }
}

}  // namespace sdlqr::closedloop
