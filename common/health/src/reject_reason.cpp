#include "sdlqr/health/reject_reason.hpp"

namespace sdlqr {

namespace {

struct ReasonNames {
  const char* name;
  const char* counter;
};

// Indexed by RejectReason.
constexpr ReasonNames kNames[] = {
    {"none", "reject.none"},
    {"decode", "reject.decode"},
    {"size", "reject.size"},
    {"nonfinite", "reject.nonfinite"},
    {"quaternion", "reject.quaternion"},
    {"range", "reject.range"},
    {"enum", "reject.enum"},
    {"status", "reject.status"},
    {"time_backwards", "reject.time_backwards"},
    {"time_future", "reject.time_future"},
    {"time_gap", "reject.time_gap"},
    {"stale", "reject.stale"},
    {"no_clock", "reject.no_clock"},
    {"gated", "reject.gated"},
    {"superseded", "reject.superseded"},
    {"queue_full", "reject.queue_full"},
    {"unstable", "reject.unstable"},
    {"refused", "reject.refused"},
    {"unsigned", "reject.unsigned"},
    {"bad_mac", "reject.bad_mac"},
    {"replayed", "reject.replayed"},
    {"sig_window", "reject.sig_window"},
};
static_assert(sizeof(kNames) / sizeof(kNames[0]) == kRejectReasonCount, "one name per reason");

const ReasonNames& namesOf(RejectReason reason) {
  static constexpr ReasonNames kUnknown{"unknown", "reject.unknown"};
  const auto i = static_cast<int>(reason);
  return i >= 0 && i < kRejectReasonCount ? kNames[i] : kUnknown;
}

}  // namespace

const char* reasonName(RejectReason reason) { return namesOf(reason).name; }
const char* counterName(RejectReason reason) { return namesOf(reason).counter; }

}  // namespace sdlqr
