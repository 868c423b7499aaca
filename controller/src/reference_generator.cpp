#include "sdlqr/controller/reference_generator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"

namespace sdlqr::controller {

const char* toString(FlightPhase phase) {
  switch (phase) {
    case FlightPhase::kIdle: return "idle";
    case FlightPhase::kTakeoff: return "takeoff";
    case FlightPhase::kHold: return "hold";
    case FlightPhase::kTrajectory: return "trajectory";
    case FlightPhase::kExit: return "exit";
    case FlightPhase::kLanding: return "landing";
  }
  return "unknown";
}

namespace {

LqrParams withGravity(double gravity) {
  LqrParams lqr;
  lqr.gravity = gravity;
  return lqr;
}

}  // namespace

ReferenceGenerator::ReferenceGenerator(const ControllerParams& params, double gravity)
    : params_(params),
      gravity_(gravity),
      lqr_(withGravity(gravity)),
      transition_(params.transition, lqr_),
      last_u_(makeInput(Vec3::Zero(), gravity)) {}

void ReferenceGenerator::setLimits(const LqrParams& lqr) {
  lqr_ = lqr;
  transition_.setLimits(lqr);
}

std::string ReferenceGenerator::setTrajectory(const Trajectory& trajectory, int64_t now_utime) {
  if (phase_ == FlightPhase::kIdle || phase_ == FlightPhase::kLanding) return "not flying";
  // The inputs of its samples within the limits; their consistency (the paper's ellipse has none) is
  // the sender's affair: the guard watches the flight.
  const trajectory::FeasibilityLimits limits = trajectory::FeasibilityLimits::from(
      lqr_, params_.guard.max_speed, std::numeric_limits<double>::infinity());
  const trajectory::FeasibilityReport report = trajectory::checkFeasibility(trajectory, limits, gravity_);
  if (report.feasible()) return loadTrajectory(trajectory, now_utime);
  if (params_.trajectory_beyond_limits == UploadBeyondLimits::kScale) return loadScaled(trajectory, limits, now_utime);
  return "beyond the vehicle:" + trajectory::describeViolations(report, limits);
}

std::string ReferenceGenerator::loadScaled(const Trajectory& trajectory, const trajectory::FeasibilityLimits& limits,
                                           int64_t now_utime) {
  const trajectory::SpeedFit fit = trajectory::fitSpeed(trajectory::givenPathAtSpeed(trajectory, gravity_),
                                                        trajectory::peakSpeed(trajectory), limits, gravity_);
  if (fit.feasible_speed <= 0.0) return trajectory::describeFit(fit, limits);
  const std::string error = loadTrajectory(fit.trajectory, now_utime);
  if (!error.empty()) return error;
  ++trajectories_scaled_;
  last_scaling_ = trajectory::describeFit(fit, limits);
  return {};
}

std::string ReferenceGenerator::loadTrajectory(const Trajectory& trajectory, int64_t now_utime) {
  const int64_t start_utime = trajectory.start_utime > 0 ? trajectory.start_utime : now_utime;
  const std::string error = tracker_.load(trajectory, static_cast<double>(start_utime) * 1e-6);
  if (!error.empty()) return error;
  trajectory_seq_ = trajectory.seq;
  path_speed_ = trajectory::peakSpeed(trajectory);
  phase_ = FlightPhase::kTrajectory;
  entry_pending_ = params_.transition.enabled;
  entering_ = false;
  return {};
}

bool ReferenceGenerator::setTrackingMode(ReferenceMode mode, int64_t now_utime) {
  if (mode != ReferenceMode::kSpatial && mode != ReferenceMode::kTemporal) return false;
  if (!tracker_.loaded()) return true;
  return tracker_.setMode(mode, static_cast<double>(now_utime) * 1e-6);
}

void ReferenceGenerator::handleCommand(const Command& command) {
  const bool flying = phase_ != FlightPhase::kIdle;
  const bool rejoined = rejoined_;
  rejoined_ = false;
  const double takeoff_height = command.position[2] > 0.0 ? command.position[2] : 1.0;
  switch (command.command) {
    case CommandType::kTakeoff:
      if (!flying) {
        takeoff_pending_ = true;
        pending_takeoff_height_ = takeoff_height;
      } else if (rejoined && phase_ == FlightPhase::kHold) {
        // The take-off this flight began with: its height above the ground is the held setpoint.
        setpoint_[2] = ground_z_ + takeoff_height;
        recovery_keeps_height_ = true;
      }
      break;
    case CommandType::kGoto:
      if (flying) {
        recovering_ = false;
        if (beginExit(&command.position, command.yaw, FlightPhase::kHold)) break;
        tracker_.clear();
        hold(command.position, command.yaw);
      }
      break;
    case CommandType::kLand:
      takeoff_pending_ = false;
      recovering_ = false;
      if (flying) {
        if (beginExit(nullptr, yaw_, FlightPhase::kLanding)) break;
        tracker_.clear();
        phase_ = FlightPhase::kLanding;
        // The descent starts from the estimate of the next tick, not from whichever estimate
        // happened to arrive before the command: the same tick gives the same ramp on the bus and
        // in a replay that delivers the command just before that tick.
        landing_pending_ = true;
        landed_since_utime_ = -1;
      }
      break;
    case CommandType::kDisarm:
      takeoff_pending_ = false;
      recovering_ = false;
      phase_ = FlightPhase::kIdle;
      break;
    case CommandType::kArm:
      break;
  }
}

void ReferenceGenerator::startTakeoff(const StateEstimate& estimate, double height) {
  ground_z_ = estimate.position[2];
  ramp_position_ = estimate.position;
  ramp_target_z_ = ground_z_ + height;
  setpoint_ = Vec3(estimate.position[0], estimate.position[1], ramp_target_z_);
  yaw_ = quat::yaw(estimate.orientation);
  phase_ = FlightPhase::kTakeoff;
  takeoff_pending_ = false;
}

void ReferenceGenerator::rejoin(const StateEstimate& estimate) {
  // The ground plane z = 0 stands in for the take-off height this instance never saw.
  ground_z_ = 0.0;
  const double z = takeoff_pending_ ? ground_z_ + pending_takeoff_height_ : estimate.position[2];
  recovery_keeps_height_ = takeoff_pending_;
  takeoff_pending_ = false;
  hold(Vec3(estimate.position[0], estimate.position[1], z), quat::yaw(estimate.orientation));
  rejoined_ = true;
  recovering_ = true;
}

// Where the recovering vehicle is (nothing to chase but level and rest) until it is level and
// stopped; from then the hold, set there.
Vec3 ReferenceGenerator::recoveryReference(const StateEstimate& estimate) {
  const bool level = quat::tilt(estimate.orientation) <= params_.recovery_tilt_deg * M_PI / 180.0;
  if (!level || estimate.velocity.norm() > params_.recovery_speed) return estimate.position;
  recovering_ = false;
  setpoint_ = Vec3(estimate.position[0], estimate.position[1],
                   recovery_keeps_height_ ? setpoint_[2] : estimate.position[2]);
  return setpoint_;
}

void ReferenceGenerator::hold(const Vec3& position, double yaw) {
  setpoint_ = position;
  yaw_ = yaw;
  phase_ = FlightPhase::kHold;
}

bool ReferenceGenerator::landedAt(const StateEstimate& estimate) {
  const bool resting = estimate.position[2] < ground_z_ + 0.1 && estimate.velocity.norm() < params_.landed_speed;
  if (!resting) {
    landed_since_utime_ = -1;
    return false;
  }
  if (landed_since_utime_ < 0) landed_since_utime_ = estimate.utime;
  return static_cast<double>(estimate.utime - landed_since_utime_) * 1e-6 >= params_.landed_time;
}

bool ReferenceGenerator::update(const StateEstimate& estimate, Reference& out) {
  const double dt = last_utime_ < 0 ? 0.0 : std::max(0.0, static_cast<double>(estimate.utime - last_utime_) * 1e-6);
  last_utime_ = estimate.utime;
  last_estimate_position_ = estimate.position;
  last_estimate_velocity_ = estimate.velocity;

  Vec3 position_ref = setpoint_;
  Vec3 velocity_ref = Vec3::Zero();
  switch (phase_) {
    case FlightPhase::kIdle: {
      if (estimate.status != EstimatorStatus::kOk) return false;
      const bool first_estimate = !seen_estimate_;
      seen_estimate_ = true;
      if (first_estimate && estimate.position[2] > params_.rejoin_height) {
        rejoin(estimate);
        position_ref = recoveryReference(estimate);
        break;
      }
      if (!takeoff_pending_) return false;
      startTakeoff(estimate, pending_takeoff_height_);
      position_ref = ramp_position_;
      break;
    }
    case FlightPhase::kTakeoff:
      ramp_position_[2] = std::min(ramp_target_z_, ramp_position_[2] + params_.takeoff_speed * dt);
      position_ref = ramp_position_;
      if (ramp_position_[2] >= ramp_target_z_) {
        hold(setpoint_, yaw_);
      } else {
        velocity_ref[2] = params_.takeoff_speed;
      }
      break;
    case FlightPhase::kHold:
      if (recovering_) position_ref = recoveryReference(estimate);
      break;
    case FlightPhase::kTrajectory:
      return trackTrajectory(estimate, out);
    case FlightPhase::kExit:
      return flyExit(estimate, out);
    case FlightPhase::kLanding: {
      if (landing_pending_) {
        ramp_position_ = Vec3(estimate.position[0], estimate.position[1], std::max(estimate.position[2], ground_z_));
        landing_pending_ = false;
      }
      if (landedAt(estimate)) {
        phase_ = FlightPhase::kIdle;
        return false;
      }
      // The reference keeps sinking below the ground (bounded by landing_undershoot) and keeps
      // asking for the landing speed, so thrust stays below hover after touchdown even when
      // the estimate is off, until the bodyrate loop detects the landing and disarms.
      const double bottom = ground_z_ - params_.landing_undershoot;
      ramp_position_[2] = std::max(bottom, ramp_position_[2] - params_.landing_speed * dt);
      position_ref = ramp_position_;
      velocity_ref[2] = -params_.landing_speed;
      break;
    }
  }

  emit(out, makeState(position_ref, quat::fromYaw(yaw_), velocity_ref), makeInput(Vec3::Zero(), gravity_),
       ReferenceMode::kSetpoint, 0, 0.0, -1);
  return true;
}

void ReferenceGenerator::emit(Reference& out, const State& x, const Input& u, ReferenceMode mode, int index,
                              double gamma, int64_t trajectory_seq) {
  out.x = x;
  out.u = u;
  out.mode = mode;
  out.index = index;
  out.gamma = gamma;
  out.trajectory_seq = trajectory_seq;
  last_x_ = x;
  last_u_ = u;
}

}  // namespace sdlqr::controller
