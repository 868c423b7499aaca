#include "sdlqr/lowlevel/lowlevel_core.hpp"

#include <algorithm>

namespace sdlqr::lowlevel {

LowlevelCore::LowlevelCore(const VehicleParams& vehicle, const LowlevelParams& params, double gravity,
                           const FaultParams& faults, const ValidationLimits& limits)
    : loop_(vehicle, params, limits, gravity),
      faults_(faults),
      limits_(limits),
      imu_watchdog_(health_.counters(), "imu", faults.lowlevel_imu_timeout_s),
      rate_watchdog_(health_.counters(), "rate_cmd", params.rate_cmd_timeout) {
  const LowlevelCounters& c = loop_.counters();
  Counters& named = health_.counters();
  events_ = {{
      {named.add("imu.resyncs"), &c.imu_resyncs},
      {named.add("arm.refused"), &c.arm_refused},
      {named.add("failsafe.entries"), &c.failsafe_entries},
      {named.add("failsafe.recoveries"), &c.failsafe_recoveries},
      {named.add("failsafe.touchdowns"), &c.failsafe_touchdowns},
      {named.add("disarm.auto"), &c.auto_disarms},
      {named.add("mixer.saturated_steps"), &c.saturated_steps},
      {named.add("output.nonfinite"), &c.nonfinite_outputs},
  }};
}

void LowlevelCore::mirrorEvents() {
  for (EventCounter& event : events_) {
    if (*event.value == event.reported) continue;
    health_.counters().increment(event.id, *event.value - event.reported);
    event.reported = *event.value;
  }
}

RejectReason LowlevelCore::onImu(const ImuSample& sample, Outbox& out) {
  const MotorCommand& command = loop_.step(sample);
  const RejectReason reason = loop_.lastImuReject();
  if (health_.reject(Stream::kImu, reason)) return reason;
  imu_watchdog_.feed(wall_now_s_);
  imu_utime_ = command.utime;
  out.publish(command);
  health_.setSimTime(command.utime);
  mirrorEvents();
  health_.setState(command.mode == MotorMode::kFailsafe ? ProcessState::kFailsafe : ProcessState::kRunning);
  return RejectReason::kNone;
}

RejectReason LowlevelCore::onRateCommand(const RateCommand& command) {
  return health_.admit(Stream::kRateCommand, loop_.setRateCommand(command), [&] { rate_watchdog_.feed(wall_now_s_); });
}

RejectReason LowlevelCore::onCommand(const Command& command) {
  const RejectReason reason = admitOrdered(command, limits_, command_order_, imu_utime_);
  if (health_.reject(Stream::kCommand, reason)) return reason;
  // The mission re-sends its current command (same seq) for a restarted controller: acting on
  // it again would re-arm a vehicle the failsafe has landed.
  if (command.seq == last_command_seq_) return RejectReason::kNone;
  last_command_seq_ = command.seq;
  loop_.handleCommand(command);  // a refused arm is counted by the loop ("arm.refused")
  mirrorEvents();
  return RejectReason::kNone;
}

RejectReason LowlevelCore::onParams(const ParamsUpdate& update) {
  const RejectReason reason = admitOrdered(update, limits_, params_order_, imu_utime_);
  if (health_.reject(Stream::kParams, reason)) return reason;
  if ((update.field_mask & ParamsUpdate::kMass) == 0 || loop_.setMass(update.mass)) return RejectReason::kNone;
  health_.reject(Stream::kParams, RejectReason::kRefused);
  return RejectReason::kRefused;
}

void LowlevelCore::onWallTime(double now_s) {
  wall_now_s_ = now_s;
  if (imu_watchdog_.check(now_s)) health_.setState(ProcessState::kFailsafe);
  rate_watchdog_.check(now_s);
}

int LowlevelCore::wallTimePeriodMs() const {
  return std::max(1, static_cast<int>(faults_.lowlevel_imu_timeout_s * 1e3 / 4));
}

}  // namespace sdlqr::lowlevel
