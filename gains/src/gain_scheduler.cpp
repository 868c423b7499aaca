#include "sdlqr/gains/gain_scheduler.hpp"

namespace sdlqr::gains {

namespace {

// hover_lqr and geometric use no GAINS; the paper's K is solved for them all the same, so that a
// switch back to sdlqr finds a fresh K at once. sdlqr_adaptive's is the paper's model with the
// REFERENCE's thrust gain.
ControlLaw solvedLaw(ControlLaw law) {
  const bool own = law == ControlLaw::kSdlqrIntegral || law == ControlLaw::kSdlqrActuator ||
                   law == ControlLaw::kSdlqrAdaptive;
  return own ? law : ControlLaw::kSdlqr;
}

}  // namespace

GainScheduler::GainScheduler(const LqrParams& params, double rate_hz)
    : lqr_(params),
      period_utime_(static_cast<int64_t>(1e6 / rate_hz + 0.5)),
      reference_input_(makeInput(Vec3::Zero(), params.gravity)) {}

bool GainScheduler::due(const StateEstimate& estimate) {
  if (estimate.utime < next_utime_) return false;
  next_utime_ = (estimate.utime / period_utime_ + 1) * period_utime_;
  return true;
}

SolveStatus GainScheduler::solve(const StateEstimate& estimate, GainSet& out) {
  const State x = estimate.state();
  const LqrParams& params = lqr_.params();
  const ExtendedLqrResult extended = solveLqrForLaw(x, reference_input_, params, reference_thrust_gain_);
  const LqrResult& result = extended.lqr;
  ++solves_;
  out.utime = estimate.utime;
  out.x_lin = x;
  orientation(out.x_lin).normalize();
  out.u_lin = reference_input_;
  out.q_diag = params.q_diag;
  out.r_diag = params.r_diag;
  out.dt = params.dt;
  out.residual = result.residual;
  out.iterations = result.iterations;
  out.state_seq = estimate.seq;
  out.params_seq = lqr_.seq();
  out.reference_seq = reference_seq_;
  out.method = params.method == LqrMethod::kTangent ? GainsMethod::kTangent : GainsMethod::kIterative;
  out.status = result.status;
  out.law = solvedLaw(params.law);
  out.thrust_time_constant = out.law == ControlLaw::kSdlqrActuator ? params.thrust_time_constant : 0.0;
  out.thrust_gain = reference_thrust_gain_;
  if (result.status != SolveStatus::kOk) {
    ++failures_;
    out.K.setZero();
    out.K_aug.setZero();
    return result.status;
  }
  out.K = result.K;
  out.K_aug = extended.K_aug;
  out.seq = seq_++;
  return SolveStatus::kOk;
}

}  // namespace sdlqr::gains
