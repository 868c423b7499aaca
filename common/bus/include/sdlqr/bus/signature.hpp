#pragma once
// Signing and checking the messages of a signed bus (trailer layout: signature_layout.hpp).
// HMAC-SHA256 is nettle's (Debian nettle-dev); the keyed state is prepared once, so signing and
// verifying never allocate. Pure and clock-free: the caller passes the times.

#include <nettle/hmac.h>

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "sdlqr/bus/bus_key.hpp"
#include "sdlqr/bus/replay_window.hpp"
#include "sdlqr/bus/signature_layout.hpp"
#include "sdlqr/health/reject_reason.hpp"

namespace sdlqr::bus {

// Wall-clock microseconds since 1970 as a signature timestamp (10 us units since 2015-01-01 UTC;
// 0 before 2015).
uint64_t signatureTime(int64_t unix_utime);

class BusSigner {
 public:
  explicit BusSigner(const BusKey& key);
  ~BusSigner();  // wipes the keyed state
  BusSigner(const BusSigner&) = delete;
  BusSigner& operator=(const BusSigner&) = delete;

  // Writes the trailer at payload + size: the buffer must hold size + kSignatureSize bytes.
  void sign(std::string_view channel, uint8_t* payload, size_t size, const SignatureTrailer& trailer) const;
  // True when the last kSignatureSize of `size` bytes hold this key's MAC over the rest (and the
  // channel). Compared in constant time.
  bool verify(std::string_view channel, const uint8_t* data, size_t size) const;

 private:
  void mac(std::string_view channel, const uint8_t* payload, size_t size, const uint8_t* head, uint8_t* out) const;
  hmac_sha256_ctx keyed_;
};

// The trailer fields of a signed message (size >= kSignatureSize), not verified.
SignatureTrailer trailerOf(const uint8_t* data, size_t size);

// A subscriber's check of one received message, before anything decodes it: kUnsigned (no trailer:
// shorter than one, or a MAC mismatch on bytes that are a whole unsigned encoding,
// `fits_unsigned`), kBadMac, then the replay window of the channel (kReplayed, kSignatureWindow).
// kNone: the first size - kSignatureSize bytes are the authentic payload.
RejectReason admitSigned(const BusSigner& signer, ReplayWindow& window, std::string_view channel,
                         const uint8_t* data, size_t size, bool fits_unsigned, uint64_t now);

}  // namespace sdlqr::bus
