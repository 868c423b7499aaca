#include "sdlqr/px4/bridge_core.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sdlqr/mavlink/dispatch.hpp"
#include "sdlqr/px4/estimate_messages.hpp"
#include "sdlqr/px4/frames.hpp"

namespace sdlqr::px4 {

namespace {
constexpr int64_t kClockPeriodUs = 10000;  // SIM_CLOCK every 10 ms of vehicle time, as the simulator's
}  // namespace

const char* stateName(BridgeState state) {
  switch (state) {
    case BridgeState::kWaiting: return "waiting";
    case BridgeState::kStandby: return "standby";
    case BridgeState::kStreaming: return "streaming";
    case BridgeState::kHandshake: return "handshake";
    case BridgeState::kFlying: return "flying";
    case BridgeState::kLanding: return "landing";
    case BridgeState::kTakenOver: return "taken_over";
    case BridgeState::kLinkLost: return "link_lost";
  }
  return "unknown";
}

BridgeCore::BridgeCore(const BridgeParams& params, double gravity, const ValidationLimits& limits,
                       MavlinkEndpoint& link, BridgeOptions options)
    : params_(params),
      gravity_(gravity),
      limits_(limits),
      link_(link),
      bench_(options.bench),
      clock_from_start_(options.clock_from_start),
      commands_(params.commands),
      stream_(params.offboard_stream_rate_hz) {
  const std::string invalid = params.invalidReason();
  if (!invalid.empty()) throw std::invalid_argument("px4." + invalid);
  Counters& c = health_.counters();
  ids_.setpoints = c.add("px4.setpoints");
  ids_.idle_setpoints = c.add("px4.idle_setpoints");
  ids_.estimates = c.add("px4.estimates");
  ids_.offboard_asked = c.add("px4.offboard.asked");
  ids_.offboard_refused = c.add("px4.offboard.refused");
  ids_.arm_asked = c.add("px4.arm.asked");
  ids_.arm_refused = c.add("px4.arm.refused");
  ids_.disarm_asked = c.add("px4.disarm.asked");
  ids_.commands_timed_out = c.add("px4.commands.timed_out");
  ids_.acks_unexpected = c.add("px4.acks.unexpected");
  ids_.left_by_autopilot = c.add("px4.offboard.left_by_autopilot");
  ids_.left_in_link_loss = c.add("px4.offboard.left_in_link_loss");
  ids_.no_heartbeat = c.add("failsafe.no_heartbeat");
  ids_.no_odometry = c.add("failsafe.no_odometry");
  ids_.controller_silent = c.add("failsafe.controller_silent");
  ids_.armed = c.add("px4.armed");                // gauges: PX4's state as last heard
  ids_.mode = c.add("px4.custom_mode");
  ids_.landed_state = c.add("px4.landed_state");
  ids_.link_sent = c.add("mavlink.sent");
  ids_.link_failures = c.add("mavlink.send_failures");
  ids_.frames = c.add("mavlink.frames");
  ids_.skipped_bytes = c.add("mavlink.skipped_bytes");
  ids_.clock_offset = c.add("px4.clock_offset_us");  // gauge: PX4's time of the stack's 0
  for (size_t i = 0; i < mavlink::kFrameDropCount; ++i) {
    ids_.drops[i] = c.add(std::string("mavlink.drop.") + mavlink::dropName(static_cast<mavlink::FrameDrop>(i)));
  }
  estimate_rejects_.fill(-1);
}

int BridgeCore::wallTimePeriodMs() const {
  const double finest = std::min({params_.odometry_timeout_s / 4, 1.0 / params_.idle_rate_hz, params_.commands.interval_s});
  return std::max(1, static_cast<int>(finest * 1e3));
}

// ---- from the autopilot

void BridgeCore::onBytes(const uint8_t* data, size_t size, bool datagram, Outbox& bus) {
  bus_ = &bus;
  link_.receive(data, size, datagram, [this](const mavlink::Frame& frame) {
    if (frame.source.system != params_.autopilot_system) return;  // another system on the link
    mavlink::dispatch(frame, [this](const auto& message) { handle(message); });
  });
  bus_ = nullptr;
  countMirror();
}

void BridgeCore::handle(const mavlink::Heartbeat& m) {
  if (m.autopilot == mavlink::mav_autopilot::kInvalid) return;  // a GCS or another companion, not PX4
  const FlightMode mode = flightModeOf(m.custom_mode);
  const bool was_offboard = view_.heard && view_.mode.offboard();
  view_.heard = true;
  view_.heartbeat_s = now_s_;
  view_.armed = (m.base_mode & mavlink::mav_mode_flag::kSafetyArmed) != 0;
  view_.mode = mode;
  if (was_offboard && !mode.offboard() && intent_ == FlightIntent::kFly) {
    // Who took OFFBOARD away: our own link loss (ask again once back) or a pilot / PX4's own
    // failsafe while we were there (final until the mission asks again).
    if (link_lost_in_offboard_ && params_.reengage_after_link_loss) {
      health_.counters().increment(ids_.left_in_link_loss);
    } else {
      health_.counters().increment(ids_.left_by_autopilot);
      taken_over_ = true;
    }
  }
  if (mode.offboard()) link_lost_in_offboard_ = false;
  Counters& c = health_.counters();
  c.set(ids_.armed, view_.armed ? 1 : 0);
  c.set(ids_.mode, m.custom_mode);
  if (!streams_requested_) requestStreams();
}

void BridgeCore::handle(const mavlink::Odometry& m) {
  RejectReason reason = RejectReason::kNone;
  StateEstimate estimate = estimateFromOdometry(m, &reason);
  publishEstimate(estimate, reason, "odometry");
}

void BridgeCore::handle(const mavlink::AttitudeQuaternion& m) { last_attitude_ = m; }

void BridgeCore::handle(const mavlink::LocalPositionNed& m) {
  // Only where PX4 streams no ODOMETRY, paired with an attitude of the same instant (50 ms).
  const bool odometry_fresh = view_.odometry_seen && now_s_ - view_.odometry_s <= params_.odometry_timeout_s;
  if (odometry_fresh || !last_attitude_) return;
  const int64_t gap_ms = static_cast<int64_t>(m.time_boot_ms) - static_cast<int64_t>(last_attitude_->time_boot_ms);
  if (std::abs(gap_ms) > 50) return;
  publishEstimate(estimateFromPositionAndAttitude(m, *last_attitude_), RejectReason::kNone, "position");
}

int64_t BridgeCore::stackTime(int64_t px4_utime) {
  if (clock_offset_us_ < 0) {
    clock_offset_us_ = clock_from_start_ ? px4_utime / 1'000'000 * 1'000'000 : 0;
    health_.counters().set(ids_.clock_offset, clock_offset_us_);
  }
  return px4_utime - clock_offset_us_;
}

void BridgeCore::publishEstimate(StateEstimate estimate, RejectReason reason, const char* source) {
  if (reason == RejectReason::kNone) estimate.utime = stackTime(estimate.utime);
  if (reason == RejectReason::kNone) reason = validate(estimate, limits_);
  if (reason == RejectReason::kNone) reason = estimate_clock_.offer(estimate.utime);
  if (reason != RejectReason::kNone) {
    Counters::Id& id = estimate_rejects_[static_cast<size_t>(reason)];
    if (id < 0) id = health_.counters().add(std::string("mavlink.") + source + "." + reasonName(reason));
    health_.counters().increment(id);
    return;
  }
  estimate.seq = estimate_seq_++;
  view_.odometry_s = now_s_;
  view_.odometry_seen = true;
  view_.vehicle_utime = estimate.utime;
  health_.setSimTime(estimate.utime);
  health_.counters().increment(ids_.estimates);
  last_estimate_ = estimate;
  bus_->publish(estimate);
  // The vehicle's clock for the scenario player, at each 10 ms it crossed (as the simulator's).
  const int64_t tick = estimate.utime / kClockPeriodUs * kClockPeriodUs;
  if (tick >= next_clock_utime_) {
    SimClockTick clock;
    clock.utime = tick;
    clock.seq = clock_seq_++;
    clock.period_us = kClockPeriodUs;
    bus_->publish(clock);
    next_clock_utime_ = tick + kClockPeriodUs;
  }
}

void BridgeCore::handle(const mavlink::HighresImu& m) {
  ImuSample imu = imuFromHighresImu(m);
  if (!imu.gyro.allFinite() || !imu.accel.allFinite() || clock_offset_us_ < 0) return;  // no clock yet
  imu.utime -= clock_offset_us_;
  imu.seq = imu_seq_++;
  bus_->publish(imu);
}

void BridgeCore::handle(const mavlink::ExtendedSysState& m) {
  view_.landed_state = m.landed_state;
  health_.counters().set(ids_.landed_state, m.landed_state);
}

void BridgeCore::handle(const mavlink::CommandAck& m) {
  if (m.target_system != 0 && m.target_system != params_.system_id) return;
  if (!commands_.pending(m.command)) {
    health_.counters().increment(ids_.acks_unexpected);
    return;
  }
  if (const auto result = commands_.onAck(m, now_s_, link_)) onCommandResult(*result);
}

void BridgeCore::countMirror() {
  Counters& c = health_.counters();
  const mavlink::ParserCounts& counts = link_.received();
  c.set(ids_.frames, counts.frames);
  c.set(ids_.skipped_bytes, counts.skipped_bytes);
  for (size_t i = 0; i < mavlink::kFrameDropCount; ++i) c.set(ids_.drops[i], counts.dropped[i]);
  c.set(ids_.link_sent, link_.sent());
  c.set(ids_.link_failures, link_.sendFailures());
}

// ---- from the bus

RejectReason BridgeCore::onRateCommand(const RateCommand& command) {
  RejectReason reason = validate(command, limits_);
  if (reason == RejectReason::kNone) reason = rate_time_.check(command.utime, view_.vehicle_utime);
  if (reason == RejectReason::kNone && view_.vehicle_utime >= 0 &&
      static_cast<double>(view_.vehicle_utime - command.utime) * 1e-6 > params_.rate_cmd_max_age_s) {
    reason = RejectReason::kStale;
  }
  if (reason == RejectReason::kNone && !linkUp()) reason = RejectReason::kRefused;  // the stack's failsafe
  if (health_.reject(Stream::kRateCommand, reason)) return reason;
  rate_time_.accept(command.utime);
  last_rate_cmd_s_ = now_s_;
  controller_silent_ = false;
  mavlink::SetAttitudeTarget setpoint;
  setpoint.time_boot_ms = static_cast<uint32_t>((command.utime + std::max<int64_t>(0, clock_offset_us_)) / 1000);
  setpoint.target_system = static_cast<uint8_t>(params_.autopilot_system);
  setpoint.target_component = static_cast<uint8_t>(params_.autopilot_component);
  setpoint.type_mask = mavlink::attitude_target_typemask::kAttitudeIgnore;
  setpoint.q = {1.0f, 0.0f, 0.0f, 0.0f};  // ignored; finite, as older PX4 required
  const Vec3 rate = bodyToFrd(command.body_rate);
  setpoint.body_roll_rate = static_cast<float>(rate[0]);
  setpoint.body_pitch_rate = static_cast<float>(rate[1]);
  setpoint.body_yaw_rate = static_cast<float>(rate[2]);
  setpoint.thrust = static_cast<float>(normalizedThrust(command.thrust, params_.thrust, gravity_));
  send(setpoint);
  health_.counters().increment(ids_.setpoints);
  return RejectReason::kNone;
}

void BridgeCore::send(const mavlink::SetAttitudeTarget& setpoint) {
  last_setpoint_ = setpoint;
  if (bench_) return;
  link_.send(setpoint);
  stream_.note(now_s_);
}

RejectReason BridgeCore::onCommand(const Command& command) {
  const RejectReason reason = admitOrdered(command, limits_, command_order_, view_.vehicle_utime);
  if (health_.reject(Stream::kCommand, reason)) return reason;
  // The mission re-sends its current command (same seq) for a restarted process: no new intent.
  if (command.seq == last_command_seq_) return RejectReason::kNone;
  last_command_seq_ = command.seq;
  switch (command.command) {
    case CommandType::kArm:
    case CommandType::kTakeoff:
      intent_ = FlightIntent::kFly;
      taken_over_ = false;  // the mission asks again: the pilot's or PX4's switch is answered
      break;
    case CommandType::kGoto:
      break;
    case CommandType::kLand:
      if (intent_ == FlightIntent::kFly) intent_ = FlightIntent::kLand;
      break;
    case CommandType::kDisarm:
      intent_ = FlightIntent::kDisarm;
      break;
  }
  return RejectReason::kNone;
}

}  // namespace sdlqr::px4
