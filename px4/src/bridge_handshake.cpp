// BridgeCore on wall time: the link watchdog, our heartbeat, stream requests, the offboard
// handshake and the zero-thrust setpoints on the ground (bridge_core.hpp).

#include <cmath>

#include "sdlqr/px4/bridge_core.hpp"

namespace sdlqr::px4 {

void BridgeCore::onWallTime(double now_s) {
  now_s_ = now_s;
  if (now_s >= next_heartbeat_s_) sendHeartbeat();
  if (!view_.heard) return;
  checkLink();
  if (const auto result = commands_.onTime(now_s, link_)) onCommandResult(*result);
  if (state_ == BridgeState::kLinkLost) {
    countMirror();
    return;
  }
  streamIdle();
  advanceHandshake();
  updateState();
  countMirror();
}

void BridgeCore::sendHeartbeat() {
  mavlink::Heartbeat heartbeat;
  heartbeat.type = mavlink::mav_type::kOnboardController;
  heartbeat.autopilot = mavlink::mav_autopilot::kInvalid;
  heartbeat.system_status = mavlink::mav_state::kActive;
  link_.send(heartbeat);
  next_heartbeat_s_ = now_s_ + 1.0;
}

// No HEARTBEAT for heartbeat_timeout_s, or no estimate for odometry_timeout_s once estimates
// flowed: the stack's failsafe. Back once both are fresh again; the first HEARTBEAT after the loss
// asks for the streams again (PX4 may have rebooted and forgotten them).
void BridgeCore::checkLink() {
  const bool heartbeat_lost = now_s_ - view_.heartbeat_s > params_.heartbeat_timeout_s;
  const bool odometry_lost = view_.odometry_seen && now_s_ - view_.odometry_s > params_.odometry_timeout_s;
  if (state_ == BridgeState::kLinkLost) {
    if (heartbeat_lost || odometry_lost) return;
    state_ = BridgeState::kStandby;
    return;
  }
  if (!heartbeat_lost && !odometry_lost) return;
  health_.counters().increment(heartbeat_lost ? ids_.no_heartbeat : ids_.no_odometry);
  health_.setLastError(heartbeat_lost ? "link lost: no HEARTBEAT from PX4" : "link lost: no ODOMETRY from PX4");
  if (view_.mode.offboard()) link_lost_in_offboard_ = true;
  commands_.clear();
  streams_requested_ = false;
  state_ = BridgeState::kLinkLost;
  health_.setState(ProcessState::kFailsafe);
}

void BridgeCore::requestStreams() {
  streams_requested_ = true;
  const auto interval_us = [](double hz) { return static_cast<float>(1e6 / hz); };
  sendCommand(mavlink::mav_cmd::kSetMessageInterval, mavlink::Odometry::kId, interval_us(params_.odometry_rate_hz));
  sendCommand(mavlink::mav_cmd::kSetMessageInterval, mavlink::HighresImu::kId, interval_us(params_.imu_rate_hz));
  sendCommand(mavlink::mav_cmd::kSetMessageInterval, mavlink::ExtendedSysState::kId,
              interval_us(params_.sys_state_rate_hz));
}

void BridgeCore::sendCommand(uint16_t command, float p1, float p2, float p3, float p4) {
  mavlink::CommandLong c;
  c.target_system = static_cast<uint8_t>(params_.autopilot_system);
  c.target_component = static_cast<uint8_t>(params_.autopilot_component);
  c.command = command;
  c.param1 = p1;
  c.param2 = p2;
  c.param3 = p3;
  c.param4 = p4;
  commands_.send(c, now_s_, link_);
}

bool BridgeCore::onGround() const { return view_.landed_state == mavlink::mav_landed_state::kOnGround; }

// Zero-thrust setpoints while PX4 says the vehicle is on the ground and no RATE_CMD comes: the
// stream PX4 needs before OFFBOARD (and idle rotors once armed). Never in the air, where a zero
// thrust would drop the vehicle: there a silent controller means no stream at all.
void BridgeCore::streamIdle() {
  const bool commanded = now_s_ - last_rate_cmd_s_ <= params_.rate_cmd_timeout_s;
  if (!commanded && !onGround() && view_.armed && !controller_silent_) {
    controller_silent_ = true;
    health_.counters().increment(ids_.controller_silent);
  }
  if (commanded || !onGround() || bench_ || now_s_ - last_idle_s_ < 1.0 / params_.idle_rate_hz) return;
  mavlink::SetAttitudeTarget idle;
  idle.time_boot_ms = static_cast<uint32_t>(std::max<int64_t>(0, view_.vehicle_utime + clock_offset_us_) / 1000);
  idle.target_system = static_cast<uint8_t>(params_.autopilot_system);
  idle.target_component = static_cast<uint8_t>(params_.autopilot_component);
  idle.type_mask = mavlink::attitude_target_typemask::kAttitudeIgnore;
  idle.q = {1.0f, 0.0f, 0.0f, 0.0f};
  send(idle);
  last_idle_s_ = now_s_;
  health_.counters().increment(ids_.idle_setpoints);
}

void BridgeCore::advanceHandshake() {
  if (bench_ || now_s_ < retry_after_s_) return;
  const auto ask = [this](uint16_t command, float p1, float p2, Counters::Id counter) {
    if (commands_.pending(command)) return;
    sendCommand(command, p1, p2);
    health_.counters().increment(counter);
  };
  switch (intent_) {
    case FlightIntent::kIdle: return;
    case FlightIntent::kFly:
      if (taken_over_) return;
      if (!view_.mode.offboard()) {
        if (stream_.runningFor(now_s_) >= params_.offboard_stream_s) {
          ask(mavlink::mav_cmd::kDoSetMode, static_cast<float>(mavlink::mav_mode_flag::kCustomModeEnabled),
              static_cast<float>(MainMode::kOffboard), ids_.offboard_asked);
        }
      } else if (!view_.armed) {
        ask(mavlink::mav_cmd::kComponentArmDisarm, 1.0f, 0.0f, ids_.arm_asked);
      }
      return;
    case FlightIntent::kLand:
    case FlightIntent::kDisarm:
      if (!view_.armed) {
        intent_ = FlightIntent::kIdle;
      } else if (intent_ == FlightIntent::kDisarm || onGround()) {
        ask(mavlink::mav_cmd::kComponentArmDisarm, 0.0f, 0.0f, ids_.disarm_asked);
      }
      return;
  }
}

void BridgeCore::onCommandResult(const CommandResult& result) {
  if (result.outcome == CommandOutcome::kAccepted) {
    // PX4 switched as it answered; its HEARTBEAT (1 Hz) says so later: until then, believe the ACK.
    if (result.command == mavlink::mav_cmd::kDoSetMode) view_.mode = kOffboardMode;
    if (result.command == mavlink::mav_cmd::kComponentArmDisarm) view_.armed = result.param1 != 0.0f;
    return;
  }
  Counters& c = health_.counters();
  if (result.outcome == CommandOutcome::kTimedOut) c.increment(ids_.commands_timed_out);
  if (result.command == mavlink::mav_cmd::kDoSetMode) c.increment(ids_.offboard_refused);
  if (result.command == mavlink::mav_cmd::kComponentArmDisarm) c.increment(ids_.arm_refused);
  if (result.command == mavlink::mav_cmd::kSetMessageInterval) {
    if (static_cast<uint32_t>(result.param1) == mavlink::Odometry::kId && !position_fallback_) {
      // No ODOMETRY from this PX4: LOCAL_POSITION_NED and ATTITUDE_QUATERNION instead.
      position_fallback_ = true;
      const float interval_us = static_cast<float>(1e6 / params_.odometry_rate_hz);
      sendCommand(mavlink::mav_cmd::kSetMessageInterval, mavlink::LocalPositionNed::kId, interval_us);
      sendCommand(mavlink::mav_cmd::kSetMessageInterval, mavlink::AttitudeQuaternion::kId, interval_us);
    }
    return;
  }
  health_.setLastError(std::string("MAV_CMD ") + std::to_string(result.command) + " " + outcomeName(result.outcome) +
                       (result.outcome == CommandOutcome::kRefused ? " (MAV_RESULT " + std::to_string(result.result) + ")"
                                                                   : " after " + std::to_string(result.attempts) + " sends"));
  retry_after_s_ = now_s_ + params_.handshake_retry_s;
}

void BridgeCore::updateState() {
  BridgeState next = BridgeState::kStandby;
  if (taken_over_) {
    next = BridgeState::kTakenOver;
  } else if (intent_ == FlightIntent::kFly) {
    if (view_.mode.offboard() && view_.armed) {
      next = BridgeState::kFlying;
    } else {
      next = commands_.idle() && !view_.mode.offboard() && !commands_.pending(mavlink::mav_cmd::kDoSetMode)
                 ? BridgeState::kStreaming
                 : BridgeState::kHandshake;
    }
  } else if (intent_ == FlightIntent::kLand || intent_ == FlightIntent::kDisarm) {
    next = BridgeState::kLanding;
  }
  state_ = next;
  const bool degraded = controller_silent_ || taken_over_;
  health_.setState(degraded ? ProcessState::kDegraded : ProcessState::kRunning);
}

}  // namespace sdlqr::px4
