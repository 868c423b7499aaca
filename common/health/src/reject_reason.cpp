#include "sdlqr/health/reject_reason.hpp"

namespace sdlqr {

const char* reasonName(RejectReason reason) {
  switch (reason) {
    case RejectReason::kNone: return "none";
    case RejectReason::kDecode: return "decode";
    case RejectReason::kBadSize: return "size";
    case RejectReason::kNonFinite: return "nonfinite";
    case RejectReason::kQuaternionNorm: return "quaternion";
    case RejectReason::kOutOfRange: return "range";
    case RejectReason::kBadEnum: return "enum";
    case RejectReason::kBadStatus: return "status";
    case RejectReason::kTimeBackwards: return "time_backwards";
    case RejectReason::kTimeFuture: return "time_future";
    case RejectReason::kTimeGap: return "time_gap";
    case RejectReason::kStale: return "stale";
    case RejectReason::kNoClock: return "no_clock";
    case RejectReason::kGated: return "gated";
    case RejectReason::kSuperseded: return "superseded";
    case RejectReason::kQueueFull: return "queue_full";
    case RejectReason::kUnstable: return "unstable";
    case RejectReason::kRefused: return "refused";
    case RejectReason::kCount: break;
  }
  return "unknown";
}

const char* counterName(RejectReason reason) {
  switch (reason) {
    case RejectReason::kNone: return "reject.none";
    case RejectReason::kDecode: return "reject.decode";
    case RejectReason::kBadSize: return "reject.size";
    case RejectReason::kNonFinite: return "reject.nonfinite";
    case RejectReason::kQuaternionNorm: return "reject.quaternion";
    case RejectReason::kOutOfRange: return "reject.range";
    case RejectReason::kBadEnum: return "reject.enum";
    case RejectReason::kBadStatus: return "reject.status";
    case RejectReason::kTimeBackwards: return "reject.time_backwards";
    case RejectReason::kTimeFuture: return "reject.time_future";
    case RejectReason::kTimeGap: return "reject.time_gap";
    case RejectReason::kStale: return "reject.stale";
    case RejectReason::kNoClock: return "reject.no_clock";
    case RejectReason::kGated: return "reject.gated";
    case RejectReason::kSuperseded: return "reject.superseded";
    case RejectReason::kQueueFull: return "reject.queue_full";
    case RejectReason::kUnstable: return "reject.unstable";
    case RejectReason::kRefused: return "reject.refused";
    case RejectReason::kCount: break;
  }
  return "reject.unknown";
}

}  // namespace sdlqr
