#pragma once
// Stream watchdogs: how long since the last valid message of a stream, and whether
// that is longer than its timeout. Clock-free: the caller passes the time (a main passes wall
// time, because a silent stream is exactly when no message brings simulation time).
// FaultParams is the `faults:` section of the vehicle file: the thresholds that no other
// section holds (GAINS age: controller.gains_stale_s / gains_fallback_s; RATE_CMD age:
// lowlevel.rate_cmd_timeout; the gain solver's STATE_EST age: gains.state_timeout_s).

#include <cstdint>
#include <string>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr {

class Watchdog {
 public:
  explicit Watchdog(double timeout_s) : timeout_s_(timeout_s) {}
  void feed(double now_s) { last_feed_s_ = now_s; }
  // True when the stream has been silent longer than the timeout; counts each entry into
  // silence once. Never expired before the first message (the stream has not started).
  bool check(double now_s);
  bool started() const { return last_feed_s_ >= 0.0; }
  bool expired() const { return expired_; }
  double age(double now_s) const { return started() ? now_s - last_feed_s_ : -1.0; }
  int64_t timeouts() const { return timeouts_; }
  double timeout() const { return timeout_s_; }

 private:
  double timeout_s_;
  double last_feed_s_ = -1.0;
  bool expired_ = false;
  int64_t timeouts_ = 0;
};

// Declared (key, unit, default, range, help) in common/health/params/watchdog.yaml.
struct FaultParams : DeclaredParams<FaultParams> {
  double controller_state_timeout_s;
  double lowlevel_imu_timeout_s;
  double state_max_jump_s;
  int state_jump_confirmations;

  FaultParams();
  static const ParamTable<FaultParams>& declaration();
};

}  // namespace sdlqr
