#pragma once
// MAVLink 2 message signing (mavlink.io/en/guide/message_signing.html): a signed frame carries
// 13 more bytes, link id (1), timestamp (6, little-endian, 10 us units since 2015-01-01 00:00 UTC)
// and the first 6 bytes of SHA-256(secret key (32 bytes) | the frame from its start marker through
// the CRC | link id | timestamp). SHA-256 is nettle's (Debian nettle-dev). Clock-free: callers
// pass the times.
//
// A receiver accepts a signed frame when its signature is the key's and its timestamp is newer
// than the newest accepted of its stream (system, component, link); a stream's first frame may be
// at most a minute older than the receiver's clock (the replay rule of the specification).

#include <array>
#include <cstddef>
#include <cstdint>

namespace sdlqr::mavlink {

struct SigningKey {
  std::array<uint8_t, 32> bytes{};
  ~SigningKey();  // wipes the bytes
};

inline constexpr size_t kSignatureBytes = 6;
inline constexpr uint64_t kNewStreamWindow = 6000000;  // [10 us] one minute

// The signing clock of a Unix time [us]: 10 us units since 2015-01-01 00:00:00 UTC (0 before).
uint64_t signingTime(int64_t unix_utime);

// The signature of a frame whose first `size` bytes run from its start marker through the link
// id and timestamp (the 13-byte trailer without its last 6 bytes).
std::array<uint8_t, kSignatureBytes> signatureOf(const SigningKey& key, const uint8_t* frame, size_t size);

enum class SignatureVerdict { kAccepted, kBadSignature, kReplayed };

// The receiver's side: the newest timestamp of each stream it has accepted.
class SignatureCheck {
 public:
  // `frame`: a whole signed frame of `size` bytes (trailer included). `now`: the signing clock.
  SignatureVerdict check(const SigningKey& key, const uint8_t* frame, size_t size, uint8_t system, uint8_t component,
                         uint64_t now);

 private:
  struct Stream {
    uint8_t system = 0, component = 0, link = 0;
    uint64_t newest = 0;
    bool used = false;
  };
  std::array<Stream, 16> streams_{};  // a full table forgets its oldest stream
  size_t next_slot_ = 0;
};

}  // namespace sdlqr::mavlink
