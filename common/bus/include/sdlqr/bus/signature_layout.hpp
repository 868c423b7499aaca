#pragma once
// Message signatures of a signed bus, after MAVLink 2's signing: every message carries a trailer
// after its LCM encoding, so LCM's decoders (C++ and Java, lcm-spy) still read it (they stop at the
// encoding's end) and a log stays a standard .lcmlog. Trailer, 16 bytes, big-endian:
//   uint32  link id    random per publishing process (bus Node), so a restart is a new link
//   uint48  timestamp  10 us units since 2015-01-01 UTC (MAVLink 2's), strictly increasing per link
//   48 bits MAC        HMAC-SHA256(key, channel NUL payload link timestamp), first 6 bytes
// The channel is signed too: signed bytes moved to another channel do not verify.

#include <cstddef>
#include <cstdint>

namespace sdlqr::bus {

inline constexpr size_t kSignatureSize = 16;
inline constexpr size_t kMacSize = 6;

struct SignatureTrailer {
  uint32_t link = 0;
  uint64_t timestamp = 0;  // [10 us] since 2015-01-01 UTC
};

}  // namespace sdlqr::bus
