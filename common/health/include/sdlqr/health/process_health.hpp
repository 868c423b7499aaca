#pragma once
// A process's health, as its HEARTBEAT reports it: state, simulation time, last error, the
// rejection table (stream x reason), named counters and the totals. Bus-free: a process core
// owns one; the bus (common/bus Node), the replay and the in-process loop read the same one, so
// a message rejected on the bus is counted the same way everywhere. Counting never allocates.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/health/counters.hpp"
#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/health/stream.hpp"

namespace sdlqr {

enum class ProcessState : int8_t { kStarting = 0, kRunning = 1, kDegraded = 2, kFailsafe = 3, kStopping = 4 };

class ProcessHealth {
 public:
  // Counts a rejection of a message of `stream`. Returns true when the message must be dropped
  // (reason != kNone), so a handler reads `if (health.reject(stream, reason)) return reason;`.
  bool reject(Stream stream, RejectReason reason) {
    if (reason == RejectReason::kNone) return false;
    ++rejects_[index(stream)][index(reason)];
    ++rejected_;
    return true;
  }
  // A handler in one line: counts `reason` for `stream` and returns it, or, when kNone, runs use().
  template <class Use>
  RejectReason admit(Stream stream, RejectReason reason, Use&& use) {
    if (reject(stream, reason)) return reason;
    use();
    return RejectReason::kNone;
  }
  int64_t rejections(Stream stream, RejectReason reason) const { return rejects_[index(stream)][index(reason)]; }
  int64_t rejections(RejectReason reason) const;  // over every stream
  int64_t rejected() const { return rejected_; }

  Counters& counters() { return counters_; }
  const Counters& counters() const { return counters_; }

  void setState(ProcessState state) { state_ = state; }
  ProcessState state() const { return state_; }
  void setSimTime(int64_t utime) { sim_utime_ = utime; }
  int64_t simTime() const { return sim_utime_; }
  // Allocates: for rare events only (a refused trajectory, a failed solve).
  void setLastError(std::string text) { last_error_ = std::move(text); }
  const std::string& lastError() const { return last_error_; }

  void countError() { ++errors_; }
  int64_t errors() const { return errors_; }
  void countDeadlineMiss() { ++deadline_misses_; }
  int64_t deadlineMisses() const { return deadline_misses_; }
  // Messages lost before they reached the process (sequence gaps) or by it (a full queue).
  void countDropped(int64_t count) { dropped_ += count; }
  int64_t dropped() const { return dropped_; }

  // The HEARTBEAT counter list: every "reject.<reason>" total, each non-zero
  // "reject.<stream>.<reason>", then the named counters. Allocates (once a second).
  void exportCounters(std::vector<std::string>& names, std::vector<int64_t>& values) const;
  // A counter by its HEARTBEAT name (0 when absent), for tests and comparisons.
  int64_t counter(std::string_view name) const;
  // "reject.gains.unstable=1 reject.state_est.time_future=1": every non-zero per-stream rejection.
  std::string describeRejections() const;

 private:
  static size_t index(Stream s) { return static_cast<size_t>(s); }
  static size_t index(RejectReason r) { return static_cast<size_t>(r); }

  std::array<std::array<int64_t, kRejectReasonCount>, kStreamCount> rejects_{};
  Counters counters_;
  ProcessState state_ = ProcessState::kStarting;
  int64_t sim_utime_ = 0;
  std::string last_error_;
  int64_t rejected_ = 0;
  int64_t errors_ = 0;
  int64_t deadline_misses_ = 0;
  int64_t dropped_ = 0;
};

}  // namespace sdlqr
