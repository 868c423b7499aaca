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
    : record_(record),
      sim_(plant.vehicle, withSeed(plant.sim, scenario.seed), scenario.sim),
      estimator_(config.estimator),
      lowlevel_(config.vehicle, config.lowlevel, config.lqr.gravity, config.faults, config.validation),
      controller_(config.lqr, config.controller, config.faults, config.validation),
      gains_(config.lqr, config.gains, config.faults, config.validation),
      mission_(scenario, config.trajectory, {config.lqr, config.controller.guard, config.controller.transition},
               missionOptions(command_resend_s)) {}

bool ClosedLoop::step() {
  if (mission_.finished()) return false;
  const double now_s = 1e-6 * static_cast<double>(utime());
  controller_.onWallTime(now_s);
  gains_.onWallTime(now_s);
  lowlevel_.onWallTime(now_s);
  sim_.step(*this);
  return true;
}

void ClosedLoop::run() {
  while (step()) {
  }
}

void ClosedLoop::publish(const SimTruth& m) { record(log_.sim_truth, m); }

void ClosedLoop::publish(const VioPose& m) {
  record(log_.vio_pose, m);
  estimator_.onVio(m);
}

// The mission plays what is due at this sample before the bodyrate loop steps on it.
void ClosedLoop::publish(const ImuSample& m) {
  if (record_.imu) record(log_.imu, m);
  lowlevel_.onImu(m, *this);
  estimator_.onImu(m, *this);
}

// The scenario player's clock, after the step's IMU sample, as on the bus.
void ClosedLoop::publish(const SimClockTick& m) { mission_.onClock(m.utime, *this); }

void ClosedLoop::publish(const MotorCommand& m) {
  if (record_.motor_command) record(log_.motor_command, m);
  sim_.onMotorCommand(m);
}

// The solver first: its GAINS reach the controller before the tick of the same estimate; the
// mission (throw mode) after the controller, so a throw's ARM and GOTO follow that tick.
void ClosedLoop::publish(const StateEstimate& m) {
  record(log_.state_estimate, m);
  gains_.onStateEstimate(m, *this);
  controller_.onStateEstimate(m, *this);
  mission_.onStateEstimate(m, *this);
}

void ClosedLoop::publish(const GainSet& m) {
  record(log_.gains, m);
  controller_.onGains(m);
}

void ClosedLoop::publish(const RateCommand& m) {
  record(log_.rate_command, m);
  lowlevel_.onRateCommand(m);
}

void ClosedLoop::publish(const Reference& m) {
  record(log_.reference, m);
  gains_.onReference(m);
}

void ClosedLoop::publish(const Command& m) {
  record(log_.command, m);
  lowlevel_.onCommand(m);
  controller_.onCommand(m);
}

void ClosedLoop::publish(const Disturbance& m) {
  record(log_.disturbance, m);
  sim_.onDisturbance(m);
}

void ClosedLoop::publish(const ParamsUpdate& m) {
  record(log_.params, m);
  gains_.onParams(m);
  controller_.onParams(m);
  lowlevel_.onParams(m);
}

void ClosedLoop::publish(const Trajectory& m) {
  record(log_.trajectory, m);
  controller_.onTrajectory(m);
}

}  // namespace sdlqr::closedloop
