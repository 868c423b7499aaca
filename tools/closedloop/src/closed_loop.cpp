#include "sdlqr/closedloop/closed_loop.hpp"

#include "sdlqr/mission/trajectory_request.hpp"

namespace sdlqr::closedloop {

namespace {

sim::SimParams withSeed(sim::SimParams params, long long seed) {
  params.seed = seed;
  return params;
}

}  // namespace

ClosedLoop::ClosedLoop(const StackConfig& config, const mission::Scenario& scenario, RecordOptions record)
    : config_(config),
      scenario_(scenario),
      record_(record),
      sim_(config.vehicle, withSeed(config.sim, scenario.seed)),
      estimator_(config.estimator),
      lowlevel_(config.vehicle, config.lowlevel, config.validation, config.lqr.gravity),
      controller_(config.lqr, config.controller),
      gains_(config.lqr, config.gains.rate_hz),
      player_(scenario_),
      trajectories_(scenario.events.size()) {
  for (size_t i = 0; i < scenario.events.size(); ++i) {
    if (scenario.events[i].kind == mission::ScenarioEvent::Kind::kTrajectory) {
      trajectories_[i] = mission::buildTrajectory(scenario.events[i].trajectory, config.trajectory, config.lqr,
                                                  "events[" + std::to_string(i) + "].trajectory");
    }
  }
}

void ClosedLoop::play(const mission::ScenarioEvent& event, size_t index) {
  const int64_t now = sim_.utime();
  switch (event.kind) {
    case mission::ScenarioEvent::Kind::kCommand: {
      Command command = event.command;
      command.utime = now;
      command.seq = command_seq_++;
      record(log_.command, command);
      lowlevel_.handleCommand(command);
      controller_.handleCommand(command);
      break;
    }
    case mission::ScenarioEvent::Kind::kDisturbance: {
      Disturbance disturbance = event.disturbance;
      disturbance.utime = now;
      disturbance.start_utime = now;
      disturbance.seq = disturbance_seq_++;
      record(log_.disturbance, disturbance);
      sim_.addDisturbance(disturbance);
      break;
    }
    case mission::ScenarioEvent::Kind::kParams: {
      ParamsUpdate params = event.params;
      params.utime = now;
      params.seq = params_seq_++;
      record(log_.params, params);
      gains_.applyParams(params);
      controller_.applyParams(params);
      if (params.field_mask & ParamsUpdate::kMass) lowlevel_.setMass(params.mass);
      break;
    }
    case mission::ScenarioEvent::Kind::kTrajectory: {
      Trajectory trajectory = trajectories_[index];
      trajectory.utime = now;
      trajectory.start_utime = now;
      trajectory.seq = trajectory_seq_++;
      record(log_.trajectory, trajectory);
      controller_.setTrajectory(trajectory);
      break;
    }
  }
}

bool ClosedLoop::step() {
  if (player_.finished(sim_.utime())) return false;
  const sim::StepOutput out = sim_.step();
  if (out.truth) record(log_.sim_truth, *out.truth);
  if (out.vio) {
    record(log_.vio_pose, *out.vio);
    estimator_.onVio(*out.vio);
  }
  if (!out.imu) return true;
  const ImuSample& imu = *out.imu;
  if (record_.imu) record(log_.imu, imu);
  while (const mission::ScenarioEvent* event = player_.nextDue(imu.utime)) {
    play(*event, static_cast<size_t>(event - scenario_.events.data()));
  }

  const MotorCommand motors = lowlevel_.step(imu);
  sim_.setMotorCommand(motors);
  if (record_.motor_command) record(log_.motor_command, motors);

  const std::optional<StateEstimate> estimate = estimator_.onImu(imu);
  if (!estimate) return true;
  record(log_.state_estimate, *estimate);
  if (gains_.due(*estimate)) {
    GainSet gains;
    if (gains_.solve(*estimate, gains) == SolveStatus::kOk) {
      record(log_.gains, gains);
      controller_.setGains(gains);
    }
  }
  if (controller_.onStateEstimate(*estimate, tick_)) {
    record(log_.rate_command, tick_.command);
    record(log_.reference, tick_.reference);
    lowlevel_.setRateCommand(tick_.command);
    gains_.setReference(tick_.reference);
  }
  return true;
}

void ClosedLoop::run() {
  while (step()) {
  }
}

}  // namespace sdlqr::closedloop
