#include "sdlqr/sim/sim_core.hpp"

#include <string>

namespace sdlqr::sim {

SimCore::SimCore(const VehicleParams& vehicle, const SimParams& params, const SimStress& stress)
    : simulator_(vehicle, params, static_cast<uint64_t>(params.seed), stress),
      vehicle_(vehicle),
      params_(params),
      disturbances_accepted_(health_.counters().add("disturbance.accepted")),
      crashes_(health_.counters().add("sim.crash")) {
  health_.setState(ProcessState::kRunning);
  health_.setSimTime(simulator_.utime());
  clock_.period_us = 10000;
}

RejectReason SimCore::onMotorCommand(const MotorCommand& command) {
  RejectReason reason = checkMotorCommand(command, vehicle_);
  if (reason == RejectReason::kNone) reason = motor_time_.check(command.utime, simulator_.utime());
  if (health_.reject(Stream::kMotorCommand, reason)) return reason;
  motor_time_.accept(command.utime);
  simulator_.setMotorCommand(command);
  return RejectReason::kNone;
}

RejectReason SimCore::onDisturbance(const Disturbance& disturbance) {
  RejectReason reason = checkDisturbance(disturbance, params_.disturbance);
  if (reason == RejectReason::kNone) {
    reason = disturbance_order_.offer(disturbance.utime, disturbance.seq, simulator_.utime());
  }
  if (health_.reject(Stream::kDisturbance, reason)) return reason;
  // A re-send of the pull already applied (sdlqr-mission: same seq, fresh utime) applies nothing.
  if (disturbance.seq == last_disturbance_seq_) return RejectReason::kNone;
  reason = simulator_.addDisturbance(disturbance);
  if (health_.reject(Stream::kDisturbance, reason)) return reason;
  last_disturbance_seq_ = disturbance.seq;
  health_.counters().increment(disturbances_accepted_);
  return RejectReason::kNone;
}

bool SimCore::step(Outbox& out) {
  const StepOutput output = simulator_.step();
  health_.setSimTime(simulator_.utime());
  if (output.truth) out.publish(*output.truth);
  if (output.vio) out.publish(*output.vio);
  if (output.imu) out.publish(*output.imu);
  if (simulator_.utime() % clock_.period_us == 0) {
    clock_.utime = simulator_.utime();
    out.publish(clock_);
    ++clock_.seq;
  }
  if (!simulator_.crashed() || crash_reported_) return false;
  crash_reported_ = true;
  health_.counters().increment(crashes_);
  health_.setLastError("vehicle crashed at t=" + std::to_string(simulator_.utime() * 1e-6) + " s");
  return true;
}

}  // namespace sdlqr::sim
