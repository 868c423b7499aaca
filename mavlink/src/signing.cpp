#include "sdlqr/mavlink/signing.hpp"

#include <nettle/sha2.h>

#include <algorithm>
#include <cstring>

#include "sdlqr/mavlink/frame.hpp"

namespace sdlqr::mavlink {

SigningKey::~SigningKey() {
  volatile uint8_t* p = bytes.data();
  for (size_t i = 0; i < bytes.size(); ++i) p[i] = 0;
}

uint64_t signingTime(int64_t unix_utime) {
  constexpr int64_t kEpoch2015 = 1420070400LL * 1000000;  // [us] 2015-01-01 00:00:00 UTC
  return unix_utime <= kEpoch2015 ? 0 : static_cast<uint64_t>(unix_utime - kEpoch2015) / 10;
}

std::array<uint8_t, kSignatureBytes> signatureOf(const SigningKey& key, const uint8_t* frame, size_t size) {
  sha256_ctx ctx;
  sha256_init(&ctx);
  sha256_update(&ctx, key.bytes.size(), key.bytes.data());
  sha256_update(&ctx, size, frame);
  uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(&ctx, sizeof digest, digest);
  std::array<uint8_t, kSignatureBytes> out{};
  std::memcpy(out.data(), digest, out.size());
  return out;
}

namespace {

bool sameBytes(const uint8_t* a, const uint8_t* b, size_t n) {
  uint8_t difference = 0;  // constant time: a forger learns nothing from how long the check took
  for (size_t i = 0; i < n; ++i) difference = static_cast<uint8_t>(difference | (a[i] ^ b[i]));
  return difference == 0;
}

}  // namespace

SignatureVerdict SignatureCheck::check(const SigningKey& key, const uint8_t* frame, size_t size, uint8_t system,
                                       uint8_t component, uint64_t now) {
  if (size < kHeaderSize + kChecksumSize + kSignatureSize) return SignatureVerdict::kBadSignature;
  const uint8_t* trailer = frame + size - kSignatureSize;
  const auto expected = signatureOf(key, frame, size - kSignatureBytes);
  if (!sameBytes(expected.data(), frame + size - kSignatureBytes, kSignatureBytes)) {
    return SignatureVerdict::kBadSignature;
  }
  const uint8_t link = trailer[0];
  uint64_t timestamp = 0;
  for (int i = 5; i >= 0; --i) timestamp = (timestamp << 8) | trailer[1 + i];
  auto stream = std::find_if(streams_.begin(), streams_.end(), [&](const Stream& s) {
    return s.used && s.system == system && s.component == component && s.link == link;
  });
  if (stream == streams_.end()) {
    if (timestamp + kNewStreamWindow < now) return SignatureVerdict::kReplayed;
    stream = streams_.begin() + static_cast<std::ptrdiff_t>(next_slot_);
    next_slot_ = (next_slot_ + 1) % streams_.size();
    *stream = Stream{system, component, link, timestamp, true};
    return SignatureVerdict::kAccepted;
  }
  if (timestamp <= stream->newest) return SignatureVerdict::kReplayed;
  stream->newest = timestamp;
  return SignatureVerdict::kAccepted;
}

}  // namespace sdlqr::mavlink
