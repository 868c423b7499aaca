#pragma once
// The one rejection vocabulary of every process: why a message was dropped before it could
// change anything. Each process counts a rejection under "reject.<reason>" and, per input
// stream, "reject.<stream>.<reason>" (see process_health.hpp).

#include <cstdint>

namespace sdlqr {

enum class RejectReason : int8_t {
  kNone = 0,
  kDecode,          // the bytes are no encoding of the channel's type (fingerprint, truncation)
  kBadSize,         // array lengths inconsistent, too few or too many samples
  kNonFinite,       // NaN or Inf in a field
  kQuaternionNorm,  // |q| far from 1
  kOutOfRange,      // a value beyond physical or configured limits
  kBadEnum,         // an enum field with an unknown value
  kBadStatus,       // a result that says it failed (e.g. GAINS status != OK)
  kTimeBackwards,   // utime (or (utime, seq)) not after the newest accepted on the stream
  kTimeFuture,      // utime beyond the receiver's clock plus a tolerance
  kTimeGap,         // utime further after the previous sample than a stream's gap allows
  kStale,           // too old to use on arrival (older than a timeout or than the history)
  kNoClock,         // no clock yet to judge the message's time against
  kGated,           // a measurement outside the estimator's innovation gate
  kSuperseded,      // replaced by a newer message before it could be used
  kQueueFull,       // no room to keep it (a bounded schedule is full)
  kUnstable,        // a gain whose closed loop the receiver's own check finds not Schur stable
  kRefused,         // valid on its own, refused by the algorithm in its current state
  // A signed bus (common/bus signature.hpp), checked before any of the above:
  kUnsigned,        // no signature trailer where the bus requires one
  kBadMac,          // a trailer whose MAC is not the key's over these bytes (forged or corrupted)
  kReplayed,        // its link's timestamp not after the newest accepted from that link on the channel
  kSignatureWindow, // its timestamp further from the receiver's clock than the replay window
  kCount
};
inline constexpr int kRejectReasonCount = static_cast<int>(RejectReason::kCount);

const char* reasonName(RejectReason reason);   // "nonfinite", "time_backwards", ...
const char* counterName(RejectReason reason);  // "reject.nonfinite", ...

}  // namespace sdlqr
