#pragma once
// Message validation before any algorithm sees a message (DESIGN §7: "malformed or out-of-range
// message: dropped, counted, never crashes, never reaches the controller"). Pure checks on the
// plain structs; each rejection has a reason that processes count in HEARTBEAT as "reject.<name>".

#include "sdlqr/common/messages.hpp"

namespace sdlqr {

enum class RejectReason {
  kNone = 0,
  kNonFinite,       // NaN or Inf in a field
  kQuaternionNorm,  // |q| far from 1
  kOutOfRange,      // a value beyond physical or configured limits
  kBadEnum,         // an enum field with an unknown value
  kBadSize,         // array lengths inconsistent, too few or too many samples
  kBadStatus,       // a result that says it failed (e.g. GAINS status != OK)
  kTimeBackwards,   // utime older than the newest accepted on the channel
  kTimeFuture,      // utime beyond the newest known simulation time plus a tolerance
  kCount
};

const char* counterName(RejectReason reason);  // "reject.nonfinite", ...

// Limits a validator cannot know from the message alone.
struct ValidationLimits {
  double quaternion_norm_tolerance = 0.05;  // [-] accept 0.95 <= |q| <= 1.05
  double max_position = 1000.0;             // [m] |p| per axis
  double max_velocity = 50.0;               // [m/s]
  double max_body_rate = 35.0;              // [rad/s] (2000 deg/s, a gyro's range)
  double max_thrust = 60.0;                 // [m/s^2] mass-normalized
  double max_gain = 1e4;                    // [-] |K_ij|
  int max_trajectory_samples = 100000;
};

RejectReason validate(const StateEstimate& m, const ValidationLimits& limits);
RejectReason validate(const GainSet& m, const ValidationLimits& limits);
RejectReason validate(const RateCommand& m, const ValidationLimits& limits);
RejectReason validate(const Reference& m, const ValidationLimits& limits);
RejectReason validate(const Command& m, const ValidationLimits& limits);
RejectReason validate(const ParamsUpdate& m, const ValidationLimits& limits);
RejectReason validate(const Trajectory& m, const ValidationLimits& limits);

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

}  // namespace sdlqr
