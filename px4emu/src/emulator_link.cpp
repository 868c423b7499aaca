// EmulatorCore's MAVLink side: what the companion sends, and the streams PX4 sends it
// (emulator_core.hpp).

#include "sdlqr/mavlink/dispatch.hpp"
#include "sdlqr/px4/estimate_messages.hpp"
#include "sdlqr/px4emu/emulator_core.hpp"

namespace sdlqr::px4emu {

namespace result = mavlink::mav_result;

bool EmulatorCore::targetsUs(uint8_t system, uint8_t component) const {
  const bool system_ok = system == 0 || system == config_.emulator.mav_sys_id;
  return system_ok && (component == 0 || component == px4::kAutopilotComponent);
}

void EmulatorCore::onBytes(const uint8_t* data, size_t size, bool datagram) {
  link_.receive(data, size, datagram, [this](const mavlink::Frame& frame) {
    mavlink::dispatch(frame, [&](const auto& message) { handle(message, frame); });
  });
}

void EmulatorCore::handle(const mavlink::Heartbeat&, const mavlink::Frame&) {}  // PX4 needs none of ours

void EmulatorCore::handle(const mavlink::SetAttitudeTarget& m, const mavlink::Frame&) {
  const bool rates = (m.type_mask & (mavlink::attitude_target_typemask::kBodyRollRateIgnore |
                                     mavlink::attitude_target_typemask::kBodyPitchRateIgnore)) == 0;
  const bool finite = std::isfinite(m.body_roll_rate) && std::isfinite(m.body_pitch_rate) &&
                      std::isfinite(m.body_yaw_rate) && std::isfinite(m.thrust);
  // PX4 (mavlink_receiver.cpp): a message for another system is dropped; rates are used when
  // neither roll nor pitch rate is ignored; this emulator flies rates and thrust only.
  if (!targetsUs(m.target_system, m.target_component) || !rates || !finite ||
      (m.type_mask & mavlink::attitude_target_typemask::kThrottleIgnore) != 0) {
    health_.counters().increment(ids_.setpoints_ignored);
    return;
  }
  commander_.onSetpoint(utime());  // the offboard signal, in any mode
  setpoint_ = m;
  health_.counters().increment(ids_.setpoints);
}

void EmulatorCore::handle(const mavlink::CommandLong& m, const mavlink::Frame& frame) {
  if (!targetsUs(m.target_system, m.target_component)) return;
  mavlink::CommandAck ack;
  ack.command = m.command;
  ack.result = execute(m);
  ack.target_system = frame.source.system;
  ack.target_component = frame.source.component;
  link_.send(ack);
}

uint8_t EmulatorCore::execute(const mavlink::CommandLong& m) {
  switch (m.command) {
    case mavlink::mav_cmd::kDoSetMode:
      return commander_.setMode(m, utime());
    case mavlink::mav_cmd::kComponentArmDisarm: {
      const bool was_armed = commander_.armed();
      const bool estimate_ok = estimate_ && estimate_->status == EstimatorStatus::kOk;
      const uint8_t outcome = commander_.armDisarm(m, utime(), onGround(), estimate_ok);
      if (commander_.armed() != was_armed) tellLowlevel(commander_.armed() ? CommandType::kArm : CommandType::kDisarm);
      return outcome;
    }
    case mavlink::mav_cmd::kSetMessageInterval:
      return streams_.setInterval(static_cast<uint32_t>(m.param1), m.param2);
    default:
      health_.counters().increment(ids_.commands_unsupported);
      return result::kUnsupported;
  }
}

void EmulatorCore::sendStreams() {
  const int64_t now = utime();
  streamIfDue(mavlink::Heartbeat::kId, now, [this] {
    mavlink::Heartbeat h;
    h.type = mavlink::mav_type::kQuadrotor;
    h.autopilot = mavlink::mav_autopilot::kPx4;
    h.base_mode = static_cast<uint8_t>(mavlink::mav_mode_flag::kCustomModeEnabled |
                                       (commander_.armed() ? mavlink::mav_mode_flag::kSafetyArmed : 0));
    h.custom_mode = px4::customModeOf(commander_.mode());
    h.system_status = commander_.armed() ? mavlink::mav_state::kActive : mavlink::mav_state::kStandby;
    return h;
  });
  streamIfDue(mavlink::ExtendedSysState::kId, now, [this] {
    mavlink::ExtendedSysState s;
    s.landed_state = landedState();
    return s;
  });
  streamIfDue(mavlink::HighresImu::kId, now, [this] { return px4::highresImuFromImu(imu_); });
  if (!estimate_ || estimate_->status != EstimatorStatus::kOk) return;  // EKF2 not ready: no state streams
  // Each estimate once: a stream due before a new one waits for it.
  if (estimate_->utime != odometry_sent_utime_) {
    if (streamIfDue(mavlink::Odometry::kId, now, [this] { return px4::odometryFromEstimate(*estimate_); })) {
      odometry_sent_utime_ = estimate_->utime;
    }
  }
  streamIfDue(mavlink::LocalPositionNed::kId, now, [this] { return px4::localPositionFromEstimate(*estimate_); });
  streamIfDue(mavlink::AttitudeQuaternion::kId, now, [this] { return px4::attitudeFromEstimate(*estimate_); });
}

}  // namespace sdlqr::px4emu
