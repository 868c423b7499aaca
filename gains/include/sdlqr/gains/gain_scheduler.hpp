#pragma once
// The gain solver process logic (paper §III-B: "recalculates K at 10 Hz using the linearization
// of the system at the most recent estimated state"): on a 10 Hz grid of simulation time it
// linearizes at the newest estimate and the current reference input and solves the LQR.
// Clock-free: the caller measures the solve's wall time.

#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/lqr_extensions.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/lqr_params.hpp"

namespace sdlqr::gains {

class GainScheduler {
 public:
  GainScheduler(const LqrParams& params, double rate_hz);

  // The reference input u0 of the controller's current tick (REFERENCE); hover until the first.
  void setReference(const Reference& reference) {
    reference_input_ = reference.u;
    reference_thrust_gain_ = reference.thrust_gain;
    reference_seq_ = reference.seq;
  }
  // Offers a PARAMS update to the LQR parameters under the rule the controller shares
  // (RuntimeLqrParams::apply); what is applied counts from the next solve.
  ParamsOutcome applyParams(const ParamsUpdate& update) { return lqr_.apply(update); }

  // True when this estimate is the first at or after the next grid time of the solve rate.
  bool due(const StateEstimate& estimate);
  // As due(), without moving on to the next grid time (the replay asks before it feeds).
  bool isDue(const StateEstimate& estimate) const { return estimate.utime >= next_utime_; }
  // Linearize at (estimate, reference input), discretize, solve the model of the current law
  // (lqr_extensions.hpp; GAINS law names it). `out` is complete but for solve_us. Never fills a
  // non-finite K: on failure status != kOk and K, K_aug are left zero.
  SolveStatus solve(const StateEstimate& estimate, GainSet& out);

  const LqrParams& params() const { return lqr_.params(); }
  int64_t solves() const { return solves_; }
  int64_t failures() const { return failures_; }

 private:
  RuntimeLqrParams lqr_;
  int64_t period_utime_;
  int64_t next_utime_ = 0;
  Input reference_input_;
  double reference_thrust_gain_ = 1.0;  // the model's thrust gain (REFERENCE thrust_gain)
  int64_t reference_seq_ = -1;
  int64_t seq_ = 0;
  int64_t solves_ = 0;
  int64_t failures_ = 0;
};

}  // namespace sdlqr::gains
