#include "sdlqr/px4emu/emulator_core.hpp"

#include <stdexcept>

#include "sdlqr/controller/geometric_control.hpp"
#include "sdlqr/mavlink/dispatch.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/px4/estimate_messages.hpp"
#include "sdlqr/px4/frames.hpp"

namespace sdlqr::px4emu {

namespace {

sim::SimParams checked(const EmulatorConfig& c) {
  const std::string invalid = c.emulator.invalidReason();
  if (!invalid.empty()) throw std::invalid_argument("px4_emulator." + invalid);
  return c.sim;
}

// The airframe as PX4 drives it: T = 1 is every rotor at its maximum (the mixer's full scale).
px4::ThrustMap airframeOf(const EmulatorConfig& c) {
  px4::ThrustMap map;
  map.curve = c.emulator.thrust_curve;
  const double full = 4.0 * c.vehicle.max_rotor_thrust / c.vehicle.mass;  // [m/s^2] at T = 1
  // f(h) = g / full: the hover throttle of this airframe under its thrust curve.
  const double f = c.lqr.gravity / full, k = map.curve;
  map.hover_throttle = k < 1e-9 ? f : (-(1.0 - k) + std::sqrt((1.0 - k) * (1.0 - k) + 4.0 * k * f)) / (2.0 * k);
  return map;
}

}  // namespace

EmulatorCore::EmulatorCore(const EmulatorConfig& config, const sim::SimStress& stress, px4::MavlinkEndpoint& link)
    : config_(config),
      link_(link),
      airframe_(airframeOf(config)),
      sim_(config.vehicle, checked(config), stress),
      estimator_(config.estimator),
      lowlevel_(config.vehicle, config.lowlevel, config.lqr.gravity, config.faults, config.validation),
      inner_(observer_, lowlevel_, estimator_, sim_),
      commander_(config.emulator) {
  Counters& c = health_.counters();
  ids_.offboard_entered = c.add("px4emu.offboard.entered");
  ids_.offboard_refused = c.add("px4emu.offboard.refused");
  ids_.offboard_lost = c.add("px4emu.offboard.lost");
  ids_.arms = c.add("px4emu.arms");
  ids_.arms_refused = c.add("px4emu.arms.refused");
  ids_.disarms = c.add("px4emu.disarms");
  ids_.disarms_refused = c.add("px4emu.disarms.refused");
  ids_.setpoints = c.add("px4emu.setpoints");
  ids_.setpoints_ignored = c.add("px4emu.setpoints.ignored");
  ids_.commands_unsupported = c.add("px4emu.commands.unsupported");
  ids_.armed = c.add("px4emu.armed");       // gauges
  ids_.mode = c.add("px4emu.custom_mode");
  ids_.crashes = c.add("sim.crashes");
  ids_.frames = c.add("mavlink.frames");
  ids_.sent = c.add("mavlink.sent");
  ids_.send_failures = c.add("mavlink.send_failures");
  ids_.bad_crc = c.add("mavlink.drop.bad_crc");
  ids_.unsigned_frames = c.add("mavlink.drop.unsigned");
  ids_.bad_signature = c.add("mavlink.drop.bad_signature");
  ids_.replayed = c.add("mavlink.drop.replayed");
  ids_.unknown_id = c.add("mavlink.drop.unknown_id");
  ids_.truncated = c.add("mavlink.drop.truncated");
  flown_mode_ = commander_.mode();
}

bool EmulatorCore::step(Outbox& bus) {
  bus_ = &bus;
  const double now_s = 1e-6 * static_cast<double>(utime());
  lowlevel_.onWallTime(now_s);  // simulation time is this vehicle's only clock
  const bool crashed = sim_.step(inner_.outboxOf<sim::SimCore>());
  const lowlevel::BodyrateLoop& loop = lowlevel_.loop();
  land_detector_.update(loop.mode() == MotorMode::kDisarmed || loop.mode() == MotorMode::kIdle || loop.status().maybe_landed,
                        sim_.simulator().period());
  if (commander_.armed() && loop.mode() == MotorMode::kDisarmed) commander_.onAutoDisarm();
  commander_.update(utime());
  fly();
  sendStreams();
  mirrorCounts();
  health_.setSimTime(utime());
  bus_ = nullptr;
  if (crashed && !crash_reported_) {
    crash_reported_ = true;
    health_.counters().increment(ids_.crashes);
    health_.setLastError("the vehicle crashed");
    return true;
  }
  return false;
}

RejectReason EmulatorCore::onDisturbance(const Disturbance& disturbance) { return sim_.onDisturbance(disturbance); }

uint8_t EmulatorCore::landedState() const {
  if (onGround()) return mavlink::mav_landed_state::kOnGround;
  return commander_.mode() == px4::kLandMode ? mavlink::mav_landed_state::kLanding : mavlink::mav_landed_state::kInAir;
}

// ---- what the mode flies, once per new estimate (250 Hz)

void EmulatorCore::fly() {
  if (!estimate_ || estimate_->utime == last_flown_utime_) return;
  last_flown_utime_ = estimate_->utime;
  const px4::FlightMode mode = commander_.mode();
  if (mode != flown_mode_) {  // a new mode holds where the vehicle is now
    flown_mode_ = mode;
    hold_point_ = estimate_->position;
    hold_yaw_ = quat::yaw(estimate_->orientation);
  }
  if (!commander_.armed()) return;
  if (mode.offboard()) {
    // PX4's rate controller flies the newest setpoint until the commander leaves OFFBOARD.
    if (setpoint_) {
      const Vec3 rate = px4::frdToBody(Vec3(setpoint_->body_roll_rate, setpoint_->body_pitch_rate,
                                            setpoint_->body_yaw_rate));
      commandLowlevel(rate, px4::massNormalizedThrust(setpoint_->thrust, airframe_, config_.lqr.gravity));
    }
    return;
  }
  if (onGround()) {
    commandLowlevel(Vec3::Zero(), 0.0);  // landed in Hold or Land: idle until the land detector disarms
    return;
  }
  flyNavigation(*estimate_);
}

void EmulatorCore::flyNavigation(const StateEstimate& estimate) {
  const bool landing = commander_.mode() == px4::kLandMode;
  Vec3 position = hold_point_, velocity = Vec3::Zero();
  if (landing) {
    position[2] = estimate.position[2];  // sink at the landing speed, wherever the ground is
    velocity[2] = -config_.emulator.mpc_land_speed;
  }
  const State reference = makeState(position, quat::fromYaw(hold_yaw_), velocity);
  const controller::GeometricGains gains{config_.emulator.position_gain, config_.emulator.velocity_gain,
                                        config_.emulator.attitude_gain};
  const controller::ControlOutput out = controller::geometricControl(
      estimate.state(), reference, makeInput(Vec3::Zero(), config_.lqr.gravity), gains, config_.lqr, {});
  commandLowlevel(bodyRate(out.u), out.u[kThrust]);
}

void EmulatorCore::commandLowlevel(const Vec3& body_rate, double thrust) {
  RateCommand command;
  command.utime = utime();
  command.seq = rate_seq_++;
  command.body_rate = body_rate;
  command.thrust = thrust;
  lowlevel_.onRateCommand(command);
}

void EmulatorCore::tellLowlevel(CommandType type) {
  Command command;
  command.utime = utime();
  command.seq = command_seq_++;
  command.command = type;
  lowlevel_.onCommand(command);
}

void EmulatorCore::mirrorCounts() {
  Counters& c = health_.counters();
  const CommanderCounts& k = commander_.counts();
  c.set(ids_.offboard_entered, k.offboard_entered);
  c.set(ids_.offboard_refused, k.offboard_refused);
  c.set(ids_.offboard_lost, k.offboard_lost);
  c.set(ids_.arms, k.arms);
  c.set(ids_.arms_refused, k.arms_refused);
  c.set(ids_.disarms, k.disarms);
  c.set(ids_.disarms_refused, k.disarms_refused);
  c.set(ids_.armed, commander_.armed() ? 1 : 0);
  c.set(ids_.mode, px4::customModeOf(commander_.mode()));
  const mavlink::ParserCounts& r = link_.received();
  c.set(ids_.frames, r.frames);
  c.set(ids_.sent, link_.sent());
  c.set(ids_.send_failures, link_.sendFailures());
  c.set(ids_.bad_crc, r.droppedOf(mavlink::FrameDrop::kBadCrc));
  c.set(ids_.unsigned_frames, r.droppedOf(mavlink::FrameDrop::kUnsigned));
  c.set(ids_.bad_signature, r.droppedOf(mavlink::FrameDrop::kBadSignature));
  c.set(ids_.replayed, r.droppedOf(mavlink::FrameDrop::kReplayed));
  c.set(ids_.unknown_id, r.droppedOf(mavlink::FrameDrop::kUnknownId));
  c.set(ids_.truncated, r.droppedOf(mavlink::FrameDrop::kTruncated));
  const bool failsafe = commander_.armed() && !commander_.mode().offboard() && commander_.counts().offboard_lost > 0;
  health_.setState(failsafe ? ProcessState::kFailsafe : ProcessState::kRunning);
}

}  // namespace sdlqr::px4emu
