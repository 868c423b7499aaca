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
    : record_(record),
      duration_s_(scenario.duration),
      truth_rate_hz_(plant.sim.truth_rate_hz),
      imu_rate_hz_(plant.sim.imu.rate_hz),
      estimate_period_us_(config.estimator.outputPeriodUs()),
      sim_(plant.vehicle, withSeed(plant.sim, scenario.seed), scenario.sim),
      estimator_(config.estimator),
      lowlevel_(config.vehicle, config.lowlevel, config.lqr.gravity, config.faults, config.validation),
      controller_(config.lqr, config.controller, config.faults, config.validation),
      gains_(config.lqr, config.gains, config.faults, config.validation),
      mission_(scenario, config.trajectory, config.lqr, missionOptions(command_resend_s)) {
  reserveRecording();
}

void ClosedLoop::reserveRecording() {
  const auto count = [this](double rate_hz) { return static_cast<size_t>(std::ceil(duration_s_ * rate_hz)) + 1; };
  log_.sim_truth.reserve(count(truth_rate_hz_));
  log_.state_estimate.reserve(count(1e6 / static_cast<double>(estimate_period_us_)));
  if (record_.imu) log_.imu.reserve(count(imu_rate_hz_));
  if (record_.motor_command) log_.motor_command.reserve(count(imu_rate_hz_));  // one per IMU sample
}

void ClosedLoop::recordInto(logger::FlightLog&& storage) {
  log_ = std::move(storage);
  log_.clear();
  reserveRecording();
}

logger::FlightLog ClosedLoop::takeLog() {
  logger::FlightLog out = std::move(log_);
  log_ = logger::FlightLog();
  return out;
}

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
