// The trajectory phases of the reference generator (reference_generator.hpp): the entry into a
// path, tracking it under the guard, and the exit to a hover.
#include "sdlqr/controller/reference_generator.hpp"

#include "sdlqr/trajectory/drag_feedforward.hpp"
#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::controller {

namespace {

double secondsOf(int64_t utime) { return static_cast<double>(utime) * 1e-6; }

}  // namespace

bool ReferenceGenerator::guardTrips(const StateEstimate& estimate, const State& reference, const Input& input) {
  // The attitude the law is asked to fly: with the model's rotor drag, the reference's remapped.
  State flown = reference;
  Input flown_input = input;
  trajectory::compensateRotorDrag(flown, flown_input, gravity_, lqr_.rotorDrag());
  const trajectory::GuardTrip trip = trajectory::checkGuard(params_.guard, estimate.state(), flown);
  if (trip == trajectory::GuardTrip::kNone) return false;
  ++guard_aborts_;
  last_guard_trip_ = trip;
  tracker_.clear();
  entering_ = false;
  entry_pending_ = false;
  // Right the vehicle and stop it where it is, then hold there (as a rejoin does).
  hold(estimate.position, quat::yaw(orientation(reference)));
  recovering_ = true;
  recovery_keeps_height_ = false;
  return true;
}

void ReferenceGenerator::beginEntry(const StateEstimate& estimate, double now_s) {
  entry_pending_ = false;
  // The vehicle where it is and as fast as it goes, accelerating as the reference it flew asked.
  trajectory::FlatState from = trajectory::flatStateOf(last_x_, last_u_, 0.0, gravity_);
  from.position = estimate.position;
  from.velocity = estimate.velocity;
  from.jerk.setZero();
  const trajectory::FlatState to = trajectory::flatStateAtStart(tracker_.trajectory(), gravity_);
  if (trajectory::closeEnough(from, to, params_.transition)) return;
  if (transition_.start(from, &to, now_s, path_speed_, trajectory::TransitionKind::kEntry)) {
    entering_ = true;
    ++transitions_;
    return;
  }
  ++entries_refused_;
  tracker_.clear();
  hold(estimate.position, yaw_);
}

bool ReferenceGenerator::beginExit(const Vec3* hold_at, double yaw, FlightPhase then) {
  const bool leaving = phase_ == FlightPhase::kTrajectory || phase_ == FlightPhase::kExit;
  if (!leaving || !params_.transition.enabled || last_utime_ < 0) return false;
  // The vehicle where it was at the last tick and as fast, accelerating as the reference asked (an
  // infeasible reference, the paper's ellipse, is off the vehicle's own state: start from the vehicle).
  trajectory::FlatState from = trajectory::flatStateOf(last_x_, last_u_, 0.0, gravity_);
  from.position = last_estimate_position_;
  from.velocity = last_estimate_velocity_;
  // At rest already (the end of a rest-to-rest path): a GOTO is a reference jump, a LAND lands.
  trajectory::FlatState resting;
  resting.position = from.position;
  if (trajectory::closeEnough(from, resting, params_.transition)) return false;
  trajectory::FlatState to;
  if (hold_at) {
    to.position = *hold_at;
    to.yaw = yaw;
  }
  if (!transition_.start(from, hold_at ? &to : nullptr, secondsOf(last_utime_), path_speed_,
                         trajectory::TransitionKind::kExit)) {
    return false;
  }
  ++transitions_;
  tracker_.clear();
  entering_ = false;
  entry_pending_ = false;
  after_exit_ = then;
  phase_ = FlightPhase::kExit;
  return true;
}

bool ReferenceGenerator::trackTrajectory(const StateEstimate& estimate, Reference& out) {
  const double now = secondsOf(estimate.utime);
  if (entry_pending_) beginEntry(estimate, now);
  if (phase_ != FlightPhase::kTrajectory) return update(estimate, out);  // refused: held
  if (entering_ && transition_.finished(now)) {
    entering_ = false;
    tracker_.restart(now);
  }
  if (entering_) {
    State x;
    Input u;
    transition_.reference(now, x, u);
    if (guardTrips(estimate, x, u)) return update(estimate, out);
    emit(out, x, u, ReferenceMode::kTransition, 0, 0.0, trajectory_seq_);
  } else {
    const trajectory::TrackingOutput& tracked = tracker_.update(now, estimate.position);
    if (guardTrips(estimate, tracked.x, tracked.u)) return update(estimate, out);
    emit(out, tracked.x, tracked.u, tracker_.mode(), tracked.index, tracked.gamma, trajectory_seq_);
    // The end of an open path that still moves: stop, then hold there.
    const double end_speed = velocity(tracker_.trajectory().samples.back().x).norm();
    if (tracked.finished && end_speed > params_.transition.velocity_tolerance) {
      beginExit(nullptr, quat::yaw(orientation(tracked.x)), FlightPhase::kHold);
    }
  }
  // A GOTO or LAND after the trajectory starts from where the reference was.
  setpoint_ = position(out.x);
  yaw_ = quat::yaw(orientation(out.x));
  return true;
}

bool ReferenceGenerator::flyExit(const StateEstimate& estimate, Reference& out) {
  const double now = secondsOf(estimate.utime);
  State x;
  Input u;
  transition_.reference(now, x, u);
  if (guardTrips(estimate, x, u)) return update(estimate, out);
  emit(out, x, u, ReferenceMode::kTransition, 0, 0.0, -1);
  setpoint_ = position(x);
  yaw_ = quat::yaw(orientation(x));
  if (transition_.finished(now)) {
    if (after_exit_ == FlightPhase::kLanding) {
      phase_ = FlightPhase::kLanding;
      landing_pending_ = true;
      landed_since_utime_ = -1;
    } else {
      hold(transition_.endPosition(), transition_.endYaw());
    }
  }
  return true;
}

}  // namespace sdlqr::controller
