#include "sdlqr/controller/state_dependent_lqr.hpp"

#include <stdexcept>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/lqr_extensions.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/state_prediction.hpp"
#include "sdlqr/trajectory/drag_feedforward.hpp"

namespace sdlqr::controller {

namespace {

// The hover K is the paper's (drag-free) model's: hover_lqr takes only the feed-forward against the
// drag (lqr.model_rotor_drag), and the fallback stays the K every law can fall back on.
LqrResult solveHover(const LqrParams& lqr) {
  const State hover = makeState(Vec3::Zero(), identityQuat(), Vec3::Zero());
  LqrParams drag_free = lqr;
  drag_free.model_rotor_drag = false;
  return solveLqr(hover, makeInput(Vec3::Zero(), lqr.gravity), drag_free);
}

GainMatrix solveHoverGain(const LqrParams& lqr) {
  const LqrResult result = solveHover(lqr);
  if (result.status != SolveStatus::kOk) {
    throw std::runtime_error("no stabilizing hover gain for these weights: " +
                             std::string(result.reason ? result.reason : "solver failed"));
  }
  return result.K;
}

// Hover is invariant under a yaw rotation of the world, so the hover K at heading psi is the K at
// heading 0 applied to the state expressed in a frame yawed by -psi.
GainMatrix yawedHoverGain(const GainMatrix& K0, double yaw) {
  const Mat3 rz = quat::rotationMatrix(quat::fromYaw(-yaw));
  GainMatrix K;
  K.middleCols<3>(kPos) = K0.middleCols<3>(kPos) * rz;
  K.middleCols<4>(kQuat) = K0.middleCols<4>(kQuat) * quat::leftMatrix(quat::fromYaw(-yaw));
  K.middleCols<3>(kVel) = K0.middleCols<3>(kVel) * rz;
  return K;
}

// The error the integral integrates. A spatially tracked path's reference is the point of the path
// nearest the vehicle, so the error along the path is the reference's choice, not the vehicle's
// fault: integrated, it holds the vehicle back (a rest-to-rest path creeps off its start only as the
// vehicle moves). Along the path it is left out; at a reference at rest on such a path (its start)
// nothing is integrated.
bool integrableError(const Reference& reference, Vec3& error) {
  if (reference.mode != ReferenceMode::kSpatial) return true;
  const Vec3 along = velocity(reference.x);
  const double speed = along.norm();
  if (speed < 0.1) return false;
  error -= error.dot(along / speed) * (along / speed);
  return true;
}

int64_t periodUtime(const ControllerParams& params) { return static_cast<int64_t>(1e6 / params.rate_hz + 0.5); }
int64_t maxPredictionUtime(const ControllerParams& params) {
  return static_cast<int64_t>(1e6 * params.max_prediction_s + 0.5);
}

}  // namespace

StateDependentLqr::StateDependentLqr(const LqrParams& lqr, const ControllerParams& params)
    : lqr_(lqr),
      params_(params),
      references_(params, lqr.gravity),
      fallback_K_(solveHoverGain(lqr)),
      thrust_model_(lqr.gravity),
      tick_law_(lqr.law),
      last_thrust_(lqr.gravity) {
  references_.setLimits(lqr);
}

StateDependentLqr::GainSlot& StateDependentLqr::slotFor(ControlLaw law) {
  return law == ControlLaw::kSdlqrIntegral ? integral_gains_ : actuator_gains_;
}

void StateDependentLqr::setGains(const GainSet& gains) {
  if (gains.law == ControlLaw::kSdlqrIntegral || gains.law == ControlLaw::kSdlqrActuator) {
    GainSlot& slot = slotFor(gains.law);
    if (slot.has && gains.utime < slot.gains.utime) return;
    slot.gains = gains;
    slot.has = true;
    return;
  }
  if (has_gains_ && gains.utime < gains_.utime) return;  // a late, older solve
  gains_ = gains;
  has_gains_ = true;
}

void StateDependentLqr::handleCommand(const Command& command) {
  // The mission re-sends its current command with the same seq (so a restarted controller learns
  // the setpoint); this instance has acted on it already.
  if (command.seq == command_seq_handled_) return;
  references_.handleCommand(command);
  command_seq_handled_ = command.seq;
}

std::string StateDependentLqr::setTrajectory(const Trajectory& trajectory) {
  return references_.setTrajectory(trajectory, latest_.utime);
}

ParamsOutcome StateDependentLqr::applyParams(const ParamsUpdate& update) {
  RuntimeLqrParams next = lqr_;
  const ParamsOutcome outcome = next.apply(update);
  if (outcome != ParamsOutcome::kApplied) return outcome;
  if (update.field_mask & ParamsUpdate::kWeights) {
    const LqrResult hover = solveHover(next.params());
    if (hover.status != SolveStatus::kOk) return ParamsOutcome::kInvalid;
    fallback_K_ = hover.K;
  }
  if (update.field_mask & ParamsUpdate::kTracking) references_.setTrackingMode(update.tracking, latest_.utime);
  // A law switched to the integral starts it from zero (the transfer takes the command over).
  if (next.params().law != lqr_.params().law) integral_.reset();
  lqr_ = next;
  references_.setLimits(lqr_.params());
  return outcome;
}

const GainMatrix& StateDependentLqr::chooseGain(int64_t now_utime, GainsFreshness& freshness, int64_t& gains_seq) {
  const double age = has_gains_ ? static_cast<double>(now_utime - gains_.utime) * 1e-6 : 1e9;
  if (age <= params_.gains_fallback_s) {
    freshness = age <= params_.gains_stale_s ? GainsFreshness::kFresh : GainsFreshness::kStale;
    gains_seq = gains_.seq;
    return gains_.K;
  }
  freshness = GainsFreshness::kFallback;
  gains_seq = -1;
  return fallback_K_;
}

void StateDependentLqr::hoverGain(const Reference& reference, GainMatrix& K, Quat& q_lin) const {
  const double yaw = quat::yaw(orientation(reference.x));
  K = yawedHoverGain(fallback_K_, yaw);
  q_lin = quat::fromYaw(yaw);
}

// The paper's law: the newest K, stale, or the hover K after the fallback age; `u_ref` the
// feed-forward (the reference's, or sdlqr_adaptive's thrust over the estimated gain).
StateDependentLqr::LawTick StateDependentLqr::lqrTick(const StateEstimate& estimate, const Reference& reference,
                                                      const Input& u_ref) {
  LawTick tick;
  const GainMatrix& chosen = chooseGain(estimate.utime, tick.freshness, tick.gains_seq);
  GainMatrix yawed;
  const GainMatrix* K = &chosen;
  Quat q_lin = orientation(gains_.x_lin);
  if (tick.freshness == GainsFreshness::kFallback) {
    hoverGain(reference, yawed, q_lin);
    K = &yawed;
  }
  const ErrorBounds bounds{params_.max_position_error, params_.max_velocity_error};
  tick.control = applyControlLaw(*K, q_lin, estimate.state(), reference.x, u_ref, lqr_.params(), bounds);
  return tick;
}

bool StateDependentLqr::extensionFresh(const GainSlot& slot, int64_t now_utime) const {
  return slot.has && static_cast<double>(now_utime - slot.gains.utime) * 1e-6 <= params_.gains_fallback_s;
}

StateDependentLqr::LawTick StateDependentLqr::computeLaw(const StateEstimate& estimate, const Reference& reference) {
  const ControlLaw law = lqr_.params().law;
  const ErrorBounds bounds{params_.max_position_error, params_.max_velocity_error};
  if (law == ControlLaw::kSdlqr) return lqrTick(estimate, reference, reference.u);
  if (law == ControlLaw::kSdlqrAdaptive) {
    Input u_ref = reference.u;
    u_ref[kThrust] /= thrust_gain_.value();
    return lqrTick(estimate, reference, u_ref);
  }
  // The laws that use no GAINS report the solver's freshness all the same (a switch back needs it).
  LawTick tick;
  int64_t solver_seq = -1;
  chooseGain(estimate.utime, tick.freshness, solver_seq);
  if (law == ControlLaw::kHoverLqr) {
    GainMatrix K;
    Quat q_lin;
    hoverGain(reference, K, q_lin);
    tick.control = applyControlLaw(K, q_lin, estimate.state(), reference.x, reference.u, lqr_.params(), bounds);
    return tick;
  }
  if (law == ControlLaw::kGeometric) {
    const GeometricGains gains{params_.geometric_position_gain, params_.geometric_velocity_gain,
                               params_.geometric_attitude_gain};
    tick.control = geometricControl(estimate.state(), reference.x, reference.u, gains, lqr_.params(), bounds);
    return tick;
  }
  const GainSlot& slot = law == ControlLaw::kSdlqrIntegral ? integral_gains_ : actuator_gains_;
  if (!extensionFresh(slot, estimate.utime)) return lqrTick(estimate, reference, reference.u);
  const double age = static_cast<double>(estimate.utime - slot.gains.utime) * 1e-6;
  tick.freshness = age <= params_.gains_stale_s ? GainsFreshness::kFresh : GainsFreshness::kStale;
  tick.gains_seq = slot.gains.seq;
  tick.extension = true;
  Input u_ref = reference.u;
  const Quat q_lin = orientation(slot.gains.x_lin);
  if (law == ControlLaw::kSdlqrIntegral) {
    u_ref += slot.gains.K_aug.middleCols<3>(kAugIntegral) * integral_.value();
    tick.control = applyControlLawWithinThrust(slot.gains.K, q_lin, estimate.state(), reference.x, u_ref,
                                               lqr_.params(), bounds);
    return tick;
  }
  u_ref += slot.gains.K_aug.col(kAugThrust) * (thrust_model_.value() - reference.u[kThrust]);
  tick.control = applyControlLaw(slot.gains.K, q_lin, estimate.state(), reference.x, u_ref, lqr_.params(), bounds);
  return tick;
}

void StateDependentLqr::updateExtensionStates(const StateEstimate& estimate, const Reference& reference,
                                              const RateCommand& command, bool headroom_scaled) {
  const double period = 1.0 / params_.rate_hz;
  thrust_model_.update(command.thrust, period, lqr_.params().thrust_time_constant);
  last_reference_position_ = position(reference.x);
  const FlightPhase phase = references_.phase();
  if (phase == FlightPhase::kHold || phase == FlightPhase::kTrajectory) {
    const ErrorBounds bounds{params_.max_position_error, params_.max_velocity_error};
    const State error = stateError(estimate.state(), reference.x, orientation(reference.x), bounds);
    Vec3 integrated = position(error);
    if (position(error).norm() < params_.integral_zone && integrableError(reference, integrated)) {
      integral_.update(integrated, period, command.saturated != 0 || headroom_scaled, params_.integral_limit);
    }
  }
}

int64_t StateDependentLqr::tickUtimeFor(const StateEstimate& received) const {
  // Ticks sit on a fixed grid of simulation time. The last estimate before a grid point is
  // carried forward to it; an estimate at or past it (the first one, or after missing ones) ticks
  // at its own time.
  if (received.utime >= next_tick_utime_) return received.utime;
  const int64_t interval = has_estimate_ ? received.utime - latest_.utime : 0;
  const int64_t lead = next_tick_utime_ - received.utime;
  const bool last_before_tick = interval > 0 && received.utime + interval > next_tick_utime_;
  if (!last_before_tick || lead > maxPredictionUtime(params_)) return -1;
  return next_tick_utime_;
}

void StateDependentLqr::updateThrustGain(const StateEstimate& received) {
  const FlightPhase phase = status_.phase;
  const bool airborne = phase == FlightPhase::kHold || phase == FlightPhase::kTrajectory || phase == FlightPhase::kExit;
  if (!has_estimate_ || !airborne || received.status != EstimatorStatus::kOk || latest_.status != EstimatorStatus::kOk) {
    return;
  }
  // Near the reference only: a vehicle held or pushed away feels forces no thrust gain explains.
  if ((received.position - last_reference_position_).norm() > params_.thrust_gain_zone) return;
  const double dt = static_cast<double>(received.utime - latest_.utime) * 1e-6;
  thrust_gain_.update(received.velocity - latest_.velocity, dt, quat::bodyZ(received.orientation.normalized()),
                      thrust_model_.value(), lqr_.params().gravity, params_.thrust_gain_time_constant,
                      params_.thrust_gain_min, params_.thrust_gain_max);
}

bool StateDependentLqr::onStateEstimate(const StateEstimate& received, Tick& out) {
  const int64_t tick_utime = tickUtimeFor(received);
  updateThrustGain(received);
  latest_ = received;
  has_estimate_ = true;
  if (tick_utime < 0) return false;
  const int64_t period = periodUtime(params_);
  next_tick_utime_ = (tick_utime / period + 1) * period;
  if (received.status == EstimatorStatus::kInitializing) return false;
  const StateEstimate estimate = tick_utime == received.utime
                                     ? received
                                     : predictEstimate(received, last_thrust_, tick_utime, lqr_.params().gravity);

  Reference& reference = out.reference;
  if (!references_.update(estimate, reference)) {
    status_.phase = references_.phase();
    // On the ground: the extensions' states start afresh at the next take-off.
    integral_.reset();
    thrust_model_.reset(lqr_.params().gravity);
    thrust_gain_.reset();
    return false;
  }
  status_.phase = references_.phase();
  trajectory::compensateRotorDrag(reference.x, reference.u, lqr_.params().gravity, lqr_.params().rotorDrag());

  const LawTick law_tick = computeLaw(estimate, reference);
  const GainsFreshness freshness = law_tick.freshness;
  const int64_t gains_seq = law_tick.gains_seq;
  ControlOutput control = law_tick.control;
  status_.law_output = control.u;
  const ControlLaw law = lqr_.params().law;
  if (has_commanded_ && (law != tick_law_ || law_tick.extension != tick_extension_)) {
    transfer_.start(last_command_, control.u, static_cast<int>(params_.switch_time_s * params_.rate_hz + 0.5));
    ++status_.law_switches;
  }
  tick_law_ = law;
  tick_extension_ = law_tick.extension;
  status_.transferring = transfer_.active();
  if (status_.transferring) {
    const ControlOutput limited = applyInputLimits(transfer_.apply(control.u), lqr_.params());
    control.u = limited.u;
    control.rate_saturated = control.rate_saturated || limited.rate_saturated;
    control.thrust_saturated = control.thrust_saturated || limited.thrust_saturated;
  }

  reference.utime = estimate.utime;
  reference.seq = reference_seq_++;
  reference.state_seq = estimate.seq;
  reference.command_seq = command_seq_handled_;
  reference.params_seq = lqr_.seq();
  reference.thrust_gain = law == ControlLaw::kSdlqrAdaptive ? thrust_gain_.value() : 1.0;

  RateCommand& command = out.command;
  command.utime = estimate.utime;
  command.seq = command_seq_++;
  command.body_rate = bodyRate(control.u);
  command.thrust = control.u[kThrust];
  command.state_seq = estimate.seq;
  command.gains_seq = gains_seq;
  command.reference_seq = reference.seq;
  command.saturated = static_cast<int8_t>((control.rate_saturated ? 1 : 0) | (control.thrust_saturated ? 2 : 0));
  command.thrust_demand = control.thrust_demand;
  command.gains_status = freshness;

  command.law = law;

  last_thrust_ = command.thrust;
  last_command_ = control.u;
  has_commanded_ = true;
  updateExtensionStates(estimate, reference, command, control.headroom_scaled);
  status_.law = law;
  status_.extension_active = law_tick.extension;
  ++status_.ticks;
  if (estimate.utime != received.utime) ++status_.predicted_ticks;
  status_.gains = freshness;
  if (freshness == GainsFreshness::kFallback) ++status_.fallback_ticks;
  if (freshness == GainsFreshness::kStale) ++status_.stale_ticks;
  if (command.saturated) ++status_.saturated_ticks;
  return true;
}

}  // namespace sdlqr::controller
