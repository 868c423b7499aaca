#include "sdlqr/closedloop/closed_loop.hpp"

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
      sim_(plant.vehicle, withSeed(plant.sim, scenario.seed), scenario.sim),
      estimator_(config.estimator),
      lowlevel_(config.vehicle, config.lowlevel, config.lqr.gravity, config.faults, config.validation),
      controller_(config.lqr, config.controller, config.faults, config.validation),
      gains_(config.lqr, config.gains, config.faults, config.validation),
      mission_(scenario, config.trajectory, config.lqr, missionOptions(command_resend_s)) {}

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
