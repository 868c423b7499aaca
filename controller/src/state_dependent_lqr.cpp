#include "sdlqr/controller/state_dependent_lqr.hpp"

#include <stdexcept>

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/controller/state_prediction.hpp"

namespace sdlqr::controller {

namespace {

LqrResult solveHover(const LqrParams& lqr) {
  const State hover = makeState(Vec3::Zero(), identityQuat(), Vec3::Zero());
  return solveLqr(hover, makeInput(Vec3::Zero(), lqr.gravity), lqr);
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
      last_thrust_(lqr.gravity) {}

void StateDependentLqr::setGains(const GainSet& gains) {
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
  lqr_ = next;
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

bool StateDependentLqr::onStateEstimate(const StateEstimate& received, Tick& out) {
  const int64_t tick_utime = tickUtimeFor(received);
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
    return false;
  }
  status_.phase = references_.phase();

  GainsFreshness freshness = GainsFreshness::kFresh;
  int64_t gains_seq = -1;
  const GainMatrix& chosen = chooseGain(estimate.utime, freshness, gains_seq);
  GainMatrix yawed;
  const GainMatrix* K = &chosen;
  Quat q_lin = orientation(gains_.x_lin);
  if (freshness == GainsFreshness::kFallback) {
    const double yaw = quat::yaw(orientation(reference.x));
    yawed = yawedHoverGain(chosen, yaw);
    K = &yawed;
    q_lin = quat::fromYaw(yaw);
  }

  const ErrorBounds bounds{params_.max_position_error, params_.max_velocity_error};
  const ControlOutput control =
      applyControlLaw(*K, q_lin, estimate.state(), reference.x, reference.u, lqr_.params(), bounds);

  reference.utime = estimate.utime;
  reference.seq = reference_seq_++;
  reference.state_seq = estimate.seq;
  reference.command_seq = command_seq_handled_;
  reference.params_seq = lqr_.seq();

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

  last_thrust_ = command.thrust;
  ++status_.ticks;
  if (estimate.utime != received.utime) ++status_.predicted_ticks;
  status_.gains = freshness;
  if (freshness == GainsFreshness::kFallback) ++status_.fallback_ticks;
  if (freshness == GainsFreshness::kStale) ++status_.stale_ticks;
  if (command.saturated) ++status_.saturated_ticks;
  return true;
}

}  // namespace sdlqr::controller
