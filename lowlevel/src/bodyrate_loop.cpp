#include "sdlqr/lowlevel/bodyrate_loop.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <limits>
#include <stdexcept>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/lowlevel/low_pass.hpp"

namespace sdlqr::lowlevel {

namespace {

// A clock that runs backwards or jumps for this many samples in a row is a restarted publisher
// (a new simulation), not a glitch: take its time as the new reference.
constexpr int kClockResyncSamples = 100;

double requireValid(const VehicleParams& vehicle, const LowlevelParams& params, const ValidationLimits& limits,
                    double gravity) {
  std::string reason = vehicle.invalidReason();
  if (!reason.empty()) throw std::invalid_argument("vehicle." + reason);
  reason = limits.invalidReason();
  if (!reason.empty()) throw std::invalid_argument("validation." + reason);
  reason = params.invalidReason();
  if (reason.empty()) reason = params.invalidReasonFor(vehicle, gravity);
  if (reason.empty()) reason = params.invalidReasonFor(limits);
  if (!reason.empty()) throw std::invalid_argument("lowlevel." + reason);
  if (!(gravity > 0.0 && std::isfinite(gravity))) throw std::invalid_argument("gravity: must be > 0");
  return gravity;
}

}  // namespace

BodyrateLoop::BodyrateLoop(const VehicleParams& vehicle, const LowlevelParams& params, const ValidationLimits& limits,
                           double gravity)
    : vehicle_(vehicle),
      params_(params),
      gravity_(requireValid(vehicle, params, limits, gravity)),
      max_body_rate_(limits.max_body_rate),
      mass_(vehicle.mass),
      inertia_(vehicle.inertia()),
      rate_controller_(params.rate_control),
      mixer_(vehicle.effectiveness(), std::max(vehicle.min_rotor_thrust, params.idle_thrust), vehicle.max_rotor_thrust,
             params.mixer),
      attitude_filter_(params.attitude_filter, gravity),
      ground_detector_(params.ground_detector, gravity),
      failsafe_(params.failsafe) {
  status_.hover_thrust = gravity_;
  status_.command_age = std::numeric_limits<double>::infinity();
}

RejectReason BodyrateLoop::setRateCommand(const RateCommand& command) {
  const RejectReason reason = checkRateCommand(command, params_.input_limits, max_body_rate_, maxCommandThrust(),
                                               last_imu_utime_, command_utime_, params_.rate_cmd_timeout);
  if (reason != RejectReason::kNone) {
    ++counters_.rate_cmd_rejected[static_cast<size_t>(reason)];
    return reason;
  }
  command_ = command;
  command_utime_ = command.utime;
  command_pending_ = true;
  ++counters_.rate_cmd_accepted;
  return reason;
}

bool BodyrateLoop::handleCommand(const Command& command) {
  switch (command.command) {
    case CommandType::kArm:
    case CommandType::kTakeoff:
      if (status_.mode != MotorMode::kDisarmed) return true;
      // Without an IMU sample there is no attitude and no clock to fly on.
      if (last_imu_utime_ == kNoTime) {
        ++counters_.arm_refused;
        return false;
      }
      enter(MotorMode::kIdle);
      return true;
    case CommandType::kDisarm:
      enter(MotorMode::kDisarmed);
      return true;
    case CommandType::kLand:
      // In the air the controller flies the landing and the ground detector disarms.
      if (status_.mode == MotorMode::kIdle) enter(MotorMode::kDisarmed);
      return true;
    case CommandType::kGoto:
      return true;
  }
  return false;
}

bool BodyrateLoop::setMass(double mass) {
  if (!vehicle_.massInvalidReason(mass, gravity_).empty()) {
    ++counters_.mass_rejected;
    return false;
  }
  mass_ = mass;
  return true;
}

void BodyrateLoop::enter(MotorMode mode) {
  if (mode == status_.mode) return;
  status_.mode = mode;
  rate_controller_.reset();
  status_.landed_time = 0.0;
  // Every mode that waits for the controller waits for a command sent after the change.
  command_pending_ = false;
  if (mode == MotorMode::kFailsafe) {
    failsafe_.engage();
    ++counters_.failsafe_entries;
  }
}

void BodyrateLoop::updateModes() {
  const bool fresh_command = command_pending_ && status_.command_age <= params_.rate_cmd_timeout;
  switch (status_.mode) {
    case MotorMode::kIdle:
      if (fresh_command) enter(MotorMode::kRate);
      break;
    case MotorMode::kRate:
      if (status_.command_age > params_.rate_cmd_timeout) {
        // A controller that has landed may simply stop publishing: that is not an emergency.
        if (status_.maybe_landed) {
          ++counters_.auto_disarms;
          enter(MotorMode::kDisarmed);
        } else {
          enter(MotorMode::kFailsafe);
        }
      }
      break;
    case MotorMode::kFailsafe:
      if (fresh_command) {
        enter(MotorMode::kRate);
        ++counters_.failsafe_recoveries;
      }
      break;
    case MotorMode::kDisarmed:
      break;
  }
}

MotorCommand BodyrateLoop::step(const ImuSample& sample) {
  RejectReason reason = checkImu(sample, params_.input_limits, last_imu_utime_);
  const bool clock_reject = reason == RejectReason::kTimeBackwards || reason == RejectReason::kTimeGap;
  if (clock_reject && ++consecutive_time_rejects_ >= kClockResyncSamples) {
    ++counters_.imu_resyncs;
    last_imu_utime_ = kNoTime;
    command_utime_ = kNoTime;
    reason = RejectReason::kNone;
  }
  last_imu_reject_ = reason;
  if (reason != RejectReason::kNone) {
    ++counters_.imu_rejected[static_cast<size_t>(reason)];
    return output_;
  }
  consecutive_time_rejects_ = 0;
  ++counters_.imu_accepted;

  const double dt = last_imu_utime_ == kNoTime
                        ? params_.dt_min
                        : std::clamp(1e-6 * (static_cast<double>(sample.utime) - static_cast<double>(last_imu_utime_)),
                                     params_.dt_min, params_.dt_max);
  last_imu_utime_ = sample.utime;
  status_.imu_utime = sample.utime;

  ground_detector_.update(sample.gyro, sample.accel, rotor_specific_force_, dt);
  const bool at_rest_not_flying =
      (status_.mode == MotorMode::kDisarmed || status_.mode == MotorMode::kIdle) && ground_detector_.atRest();
  const double leak_time = status_.mode == MotorMode::kFailsafe ? params_.failsafe.velocity_leak_time
                                                               : params_.attitude_filter.velocity_leak_time;
  attitude_filter_.update(sample.gyro, sample.accel, dt, at_rest_not_flying, leak_time);
  // After an impact the vehicle is not moving vertically, whatever the clipped spike integrated to.
  if (ground_detector_.impact()) attitude_filter_.stopVertical();
  const Vec3 rate = attitude_filter_.bodyRate(sample.gyro);
  status_.command_age = command_utime_ == kNoTime
                            ? std::numeric_limits<double>::infinity()
                            : 1e-6 * (static_cast<double>(sample.utime) - static_cast<double>(command_utime_));

  updateModes();
  status_.rate = rate;
  status_.maybe_landed = false;
  if (status_.mode == MotorMode::kRate) flyRate(rate, dt);
  else if (status_.mode == MotorMode::kFailsafe) flyFailsafe(rate, dt);
  // Also catches a disarm decided just now by flyRate or flyFailsafe.
  if (status_.mode == MotorMode::kDisarmed || status_.mode == MotorMode::kIdle) {
    thrust_ = status_.mode == MotorMode::kIdle ? Vec4::Constant(mixer_.minThrust()) : Vec4::Zero();
    status_.rate_setpoint.setZero();
    status_.thrust_setpoint = 0.0;
    status_.torque_demand.setZero();
  }

  if (!thrust_.allFinite()) {
    // Inputs are validated, so this is a bug; never let it reach the rotors.
    ++counters_.nonfinite_outputs;
    rate_controller_.reset();
    thrust_ = output_.thrust;
  }
  rotor_specific_force_ += lagAlpha(vehicle_.motor_time_constant, dt) * (thrust_.sum() / mass_ - rotor_specific_force_);

  status_.attitude = attitude_filter_.attitude();
  status_.vertical_velocity = attitude_filter_.verticalVelocity();
  output_.utime = sample.utime;
  output_.seq = output_seq_++;
  output_.thrust = thrust_;
  output_.imu_seq = sample.seq;
  output_.armed = status_.mode != MotorMode::kDisarmed;
  output_.mode = status_.mode;
  return output_;
}

void BodyrateLoop::flyRate(const Vec3& rate, double dt) {
  const double thrust = command_.thrust;
  // The accelerometer cannot tell hover from rest; a command below hover can, when the IMU reads
  // more than the command gives: something else carries the weight. The second test keeps a
  // learned hover thrust left high (a hard climb, a fast turn) from making a hover "below hover":
  // frozen while landed, it disarmed the vehicle in the air.
  const GroundDetectorParams& ground = params_.ground_detector;
  status_.maybe_landed = ground_detector_.atRest() && thrust < ground.landed_thrust_ratio * status_.hover_thrust &&
                         ground_detector_.filteredBodyZ() - thrust > ground.support_margin;
  status_.landed_time = status_.maybe_landed ? status_.landed_time + dt : 0.0;
  if (status_.landed_time >= ground.landed_time) {
    ++counters_.auto_disarms;
    enter(MotorMode::kDisarmed);
    return;
  }
  track(rate, command_.body_rate, thrust, status_.maybe_landed, dt);
  if (!status_.maybe_landed) {
    // What the controller needs on average to hold altitude, for the failsafe to start from.
    const double vertical_thrust = thrust * quat::bodyZ(attitude_filter_.attitude()).z();
    status_.hover_thrust += lagAlpha(params_.hover_thrust_time_constant, dt) * (vertical_thrust - status_.hover_thrust);
    status_.hover_thrust = std::clamp(status_.hover_thrust, 0.5 * gravity_, 1.5 * gravity_);
  }
}

void BodyrateLoop::flyFailsafe(const Vec3& rate, double dt) {
  const FailsafeOutput out = failsafe_.step(attitude_filter_.attitude(), attitude_filter_.verticalVelocity(),
                                            status_.hover_thrust, ground_detector_, dt);
  if (out.touched_down) {
    ++counters_.failsafe_touchdowns;
    enter(MotorMode::kDisarmed);
    return;
  }
  track(rate, out.body_rate, out.thrust, false, dt);
}

void BodyrateLoop::track(const Vec3& rate, const Vec3& rate_sp, double thrust, bool landed, double dt) {
  const Vec3 angular_acceleration = rate_controller_.update(rate, rate_sp, dt, landed);
  Vec3 torque = inertia_ * angular_acceleration;
  if (params_.rate_control.gyroscopic_feedforward) torque += rate.cross(inertia_ * rate);
  const MixerResult mix = mixer_.mix(mass_ * thrust, torque);
  rate_controller_.setSaturation(mix.saturated_positive, mix.saturated_negative);
  if (mix.saturated()) ++counters_.saturated_steps;
  thrust_ = mix.thrust;
  status_.rate_setpoint = rate_sp;
  status_.thrust_setpoint = thrust;
  status_.torque_demand = torque;
  status_.mix = mix;
  status_.pid = rate_controller_.status();
}

}  // namespace sdlqr::lowlevel
