#pragma once
// A recorded flight without a bus: the in-process closed loop flies the short hover scenario of
// the replay integration test, and its messages are put in the order a recorder would have
// heard them (per IMU sample: the IMU, the STATE_EST it completed, then the scenario's commands,
// sent on the SIM_CLOCK tick that follows the step's IMU).
// A VIO pose is placed just before the IMU sample whose STATE_EST first names it (vio_seq).

#include <algorithm>
#include <functional>
#include <string>

#include "sdlqr/closedloop/closed_loop.hpp"
#include "sdlqr/replay/recomputation.hpp"

namespace sdlqr::replay::test {

inline const std::string kScenario = std::string(SDLQR_SOURCE_DIR) + "/tests/integration/replay/hover_short.yaml";

inline ReplayParams paramsOf(const closedloop::StackConfig& c) {
  ReplayParams p;
  p.estimator = c.estimator;
  p.lqr = c.lqr;
  p.controller = c.controller;
  p.gains = c.gains;
  p.faults = c.faults;
  p.validation = c.validation;
  return p;
}

struct ClosedLoopFlight {
  closedloop::StackConfig config;
  RecordedFlight flight;
};

// `edit` changes the scenario before the flight (e.g. an event's time).
inline ClosedLoopFlight flyClosedLoop(const std::function<void(mission::Scenario&)>& edit = {}) {
  mission::Scenario scenario = mission::Scenario::load(kScenario);
  if (edit) edit(scenario);
  ClosedLoopFlight out{closedloop::StackConfig::load(scenario.vehicle_path), {}};
  closedloop::RecordOptions record;
  record.imu = true;
  closedloop::ClosedLoop loop(out.config, scenario, record);
  loop.run();
  const logger::FlightLog& log = loop.log();
  RecordedFlight& f = out.flight;
  f.imu = log.imu.messages;
  f.vio_pose = log.vio_pose.messages;
  f.command = log.command.messages;
  f.trajectory = log.trajectory.messages;
  f.params = log.params.messages;
  f.state_estimate = log.state_estimate.messages;
  f.rate_command = log.rate_command.messages;
  f.reference = log.reference.messages;
  f.gains = log.gains.messages;

  size_t vio = 0, command = 0, trajectory = 0, estimate = 0;
  for (size_t i = 0; i < f.imu.size(); ++i) {
    const int64_t utime = f.imu[i].utime;
    // The STATE_EST this sample completes, if any.
    const bool completes = estimate < f.state_estimate.size() && f.state_estimate[estimate].imu_seq == f.imu[i].seq;
    if (completes) {
      while (vio < f.vio_pose.size() && f.vio_pose[vio].seq <= f.state_estimate[estimate].vio_seq) {
        f.order.push_back({InputKind::kVioPose, static_cast<int32_t>(vio++)});
      }
    }
    f.order.push_back({InputKind::kImu, static_cast<int32_t>(i)});
    if (completes) f.order.push_back({InputKind::kStateEstimate, static_cast<int32_t>(estimate++)});
    // The scenario player runs on SIM_CLOCK, which the simulator publishes after the step's IMU.
    while (command < f.command.size() && f.command[command].utime <= utime) {
      f.order.push_back({InputKind::kCommand, static_cast<int32_t>(command++)});
    }
    while (trajectory < f.trajectory.size() && f.trajectory[trajectory].utime <= utime) {
      f.order.push_back({InputKind::kTrajectory, static_cast<int32_t>(trajectory++)});
    }
  }
  return out;
}

// The replay's outputs as a recording of their own (same inputs, same order).
inline RecordedFlight withOutputs(const RecordedFlight& inputs, const ReplayOutputs& outputs) {
  RecordedFlight f = inputs;
  f.state_estimate = outputs.state_estimate;
  f.rate_command = outputs.rate_command;
  f.reference = outputs.reference;
  f.gains = outputs.gains;
  return f;
}

}  // namespace sdlqr::replay::test
