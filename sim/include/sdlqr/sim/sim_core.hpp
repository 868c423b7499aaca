#pragma once
// The simulator process, bus-free: the checks and gates of its inputs, the counters and the
// plant. sdlqr-sim paces step() against the wall clock (common/bus paced_loop.hpp) and binds
// MOTOR_CMD and DISTURBANCE to the methods; the in-process loop steps the same object.
//
//   MOTOR_CMD    checked (finite, thrust range, mode), then a TimeGate against the simulation
//                clock: older than the last applied one or stamped ahead of the clock, it is not
//                the lowlevel's answer to the current IMU sample
//   DISTURBANCE  checked, OrderGate against the clock (a replayed one is refused); the schedule
//                may be full (kQueueFull)
//   step()       one physics step; SIM_TRUTH, VIO_POSE and IMU through the Outbox, in that order
//                (the estimator then has a pose captured earlier before the sample of this step)
// No allocation in step() or on the MOTOR_CMD path.

#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"
#include "sdlqr/sim/simulator.hpp"

namespace sdlqr::sim {

class SimCore {
 public:
  // Throws std::invalid_argument when the parameters are invalid or inconsistent. `stress`: the
  // scenario's simulated world (sim/stress_params.hpp), the same on the bus and in-process.
  SimCore(const VehicleParams& vehicle, const SimParams& params, const SimStress& stress = {});

  RejectReason onMotorCommand(const MotorCommand& command);
  RejectReason onDisturbance(const Disturbance& disturbance);
  // One physics step: SIM_TRUTH, VIO_POSE, IMU when due, then SIM_CLOCK every 10 ms of simulation
  // time (the scenario player's clock: its events are given to the centisecond, and the 1 kHz
  // IMU would cost it ten times the wake-ups). Returns true on the step the vehicle crashed
  // (reported once).
  bool step(Outbox& out);

  // Ports (sdlqr/messages/ports.hpp). Every motor command is checked and counted, the newest
  // applies: a queue of one kept the oldest of each batch the bus read and dropped the rest
  // (Node::drainInbox), 11,315 of a 52 s flight on a busy machine, among them a hostile NaN
  // command the sim never judged. Every disturbance request matters: they queue, not replace.
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&SimCore::onMotorCommand, 8},
        ports::Input{&SimCore::onDisturbance, 16},
    };
  }
  using Outputs = ports::Publishes<SimTruth, VioPose, ImuSample, SimClockTick>;

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const Simulator& simulator() const { return simulator_; }

 private:
  Simulator simulator_;
  VehicleParams vehicle_;
  SimParams params_;
  ProcessHealth health_;
  TimeGate motor_time_{0};
  OrderGate disturbance_order_;
  int64_t last_disturbance_seq_ = -1;  // the mission re-sends its current pull with the same seq
  bool crash_reported_ = false;
  SimClockTick clock_;  // SIM_CLOCK, published at every clock_.period_us of simulation time
  Counters::Id disturbances_accepted_, crashes_;
};

}  // namespace sdlqr::sim
