#pragma once
// Message validation before any algorithm sees a message ("malformed or out-of-range
// message: dropped, counted, never crashes, never reaches the controller"). Pure checks on the
// plain structs; each rejection has a reason (reject_reason.hpp) that processes count in HEARTBEAT.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr {


// Limits a validator cannot know from the message alone: the `validation:` section of the vehicle
// file, read by every process that validates messages. Declared (key, unit, default, range, help)
// in common/health/params/validate.yaml. max_body_rate is the one body-rate limit of
// the stack: estimates, references, trajectories, RATE_CMD in the bodyrate loop, a PARAMS
// omega_max and the failsafe's levelling rate are all held to it.
struct ValidationLimits : DeclaredParams<ValidationLimits> {
  double quaternion_norm_tolerance;
  double max_position;
  double max_velocity;
  double max_body_rate;
  double max_thrust;
  double max_gain;
  double max_weight;
  int max_trajectory_samples;

  ValidationLimits();
  static const ParamTable<ValidationLimits>& declaration();
};

// The LQR limits of a vehicle file against the message limits, as validate(ParamsUpdate) holds a
// PARAMS update to them: "omega_max: ..." or "c_max: ..." (keys of `lqr`), empty when they fit.
std::string lqrLimitsInvalidReason(const LqrParams& lqr, const ValidationLimits& limits);

RejectReason validate(const StateEstimate& m, const ValidationLimits& limits);
RejectReason validate(const GainSet& m, const ValidationLimits& limits);
RejectReason validate(const RateCommand& m, const ValidationLimits& limits);
RejectReason validate(const Reference& m, const ValidationLimits& limits);
RejectReason validate(const Command& m, const ValidationLimits& limits);
RejectReason validate(const ParamsUpdate& m, const ValidationLimits& limits);
RejectReason validate(const Trajectory& m, const ValidationLimits& limits);

// The receiver's own stability check of a GAINS message that passed validate(): the model
// linearized at (x_lin, u_lin), discretized at dt, reduced to the 9-state tangent system, closed
// with K; kUnstable unless every eigenvalue lies inside the circle of radius max_spectral_radius.
// A rogue or corrupted K with finite, in-range entries is caught here. No heap allocation. GAINS of
// an extension (law sdlqr_integral, sdlqr_actuator) are closed on their own larger model, K_aug too.
// drag: the receiver's model's rotor drag (LqrParams::rotorDrag; none: the paper's model).
RejectReason validateClosedLoop(const GainSet& m, const RotorDrag& drag = {}, double max_spectral_radius = 0.9999);
// Spectral radius of that tangent closed loop (NaN when it cannot be formed), for tests and logs.
double closedLoopSpectralRadius(const GainSet& m, const RotorDrag& drag = {});

// Rejects utimes that go backwards on one channel, and (when a clock is known) that lie further
// than `future_tolerance_us` ahead of the newest simulation time seen by the process.
class TimeGate {
 public:
  explicit TimeGate(int64_t future_tolerance_us = 1'000'000) : future_tolerance_us_(future_tolerance_us) {}
  RejectReason check(int64_t utime, int64_t now_utime) const {
    if (last_utime_ >= 0 && utime < last_utime_) return RejectReason::kTimeBackwards;
    if (now_utime >= 0 && utime > now_utime + future_tolerance_us_) return RejectReason::kTimeFuture;
    return RejectReason::kNone;
  }
  void accept(int64_t utime) { last_utime_ = utime; }
  void reset() { last_utime_ = -1; }

 private:
  int64_t future_tolerance_us_;
  int64_t last_utime_ = -1;
};

// For rare messages that each change the flight (COMMAND, PARAMS): one not after the last accepted
// in (utime, seq) order is a replay (kTimeBackwards); one whose utime lies more than
// future_tolerance_us ahead of the process's clock (when known, >= 0) is kTimeFuture.
class OrderGate {
 public:
  explicit OrderGate(int64_t future_tolerance_us = 1'000'000) : future_tolerance_us_(future_tolerance_us) {}
  RejectReason offer(int64_t utime, int64_t seq, int64_t now_utime) {
    if (utime < last_utime_ || (utime == last_utime_ && seq <= last_seq_)) return RejectReason::kTimeBackwards;
    if (now_utime >= 0 && utime > now_utime + future_tolerance_us_) return RejectReason::kTimeFuture;
    last_utime_ = utime;
    last_seq_ = seq;
    return RejectReason::kNone;
  }

 private:
  int64_t future_tolerance_us_;
  int64_t last_utime_ = -1;
  int64_t last_seq_ = -1;
};

// For the stream that is a process's clock (STATE_EST in the controller and the gain solver): a
// utime not after the newest accepted is kTimeBackwards; a forward jump beyond max_jump_us is
// kTimeFuture until `confirmations` messages in a row, each newer than the one before and within
// max_jump_us of it, agree on the new time (a restarted estimator after a long gap). One forged
// far-future message therefore cannot move the clock and lock out the real stream.
class ClockGate {
 public:
  ClockGate(int64_t max_jump_us = 500'000, int confirmations = 5)
      : max_jump_us_(max_jump_us), confirmations_(confirmations) {}
  RejectReason offer(int64_t utime);
  int64_t now() const { return last_utime_; }  // -1 before the first accepted message

 private:
  int64_t max_jump_us_;
  int confirmations_;
  int64_t last_utime_ = -1;
  int64_t candidate_utime_ = -1;
  int candidate_count_ = 0;
};

// The admission of a rare message that changes the flight (COMMAND, PARAMS, DISTURBANCE): valid,
// then in (utime, seq) order and not from the future of the receiver's clock (now_utime, -1 if
// none yet). What every process runs for such a message, so a replayed one is refused alike.
template <class Msg>
RejectReason admitOrdered(const Msg& m, const ValidationLimits& limits, OrderGate& order, int64_t now_utime) {
  const RejectReason reason = validate(m, limits);
  return reason != RejectReason::kNone ? reason : order.offer(m.utime, m.seq, now_utime);
}

// What applying a PARAMS update to the LQR parameters (RuntimeLqrParams::apply) says, as a
// rejection: a re-send or replay is kTimeBackwards, values the LQR refuses are kRefused.
inline RejectReason rejectionOf(ParamsOutcome outcome) {
  switch (outcome) {
    case ParamsOutcome::kApplied: return RejectReason::kNone;
    case ParamsOutcome::kNotNewer: return RejectReason::kTimeBackwards;
    case ParamsOutcome::kInvalid: break;
  }
  return RejectReason::kRefused;
}

// The admission of a process's clock stream (STATE_EST in the controller and the gain solver).
inline RejectReason admitClock(const StateEstimate& m, const ValidationLimits& limits, ClockGate& clock) {
  const RejectReason reason = validate(m, limits);
  return reason != RejectReason::kNone ? reason : clock.offer(m.utime);
}

}  // namespace sdlqr
