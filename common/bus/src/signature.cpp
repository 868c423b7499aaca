#include "sdlqr/bus/signature.hpp"

#include <nettle/memops.h>

#include <cstring>

namespace sdlqr::bus {

namespace {

constexpr int64_t kSignatureEpochUtime = 1'420'070'400'000'000;  // 2015-01-01T00:00:00Z [us since 1970]
constexpr size_t kHeadSize = kSignatureSize - kMacSize;          // link id and timestamp

void putBig(uint8_t* out, uint64_t value, size_t bytes) {
  for (size_t i = 0; i < bytes; ++i) out[i] = static_cast<uint8_t>(value >> (8 * (bytes - 1 - i)));
}

uint64_t getBig(const uint8_t* in, size_t bytes) {
  uint64_t value = 0;
  for (size_t i = 0; i < bytes; ++i) value = (value << 8) | in[i];
  return value;
}

}  // namespace

uint64_t signatureTime(int64_t unix_utime) {
  return unix_utime <= kSignatureEpochUtime ? 0 : static_cast<uint64_t>(unix_utime - kSignatureEpochUtime) / 10;
}

BusSigner::BusSigner(const BusKey& key) { hmac_sha256_set_key(&keyed_, key.bytes.size(), key.bytes.data()); }

BusSigner::~BusSigner() { explicit_bzero(&keyed_, sizeof keyed_); }

void BusSigner::mac(std::string_view channel, const uint8_t* payload, size_t size, const uint8_t* head,
                    uint8_t* out) const {
  hmac_sha256_ctx ctx = keyed_;  // the keyed state, reused for every message
  static constexpr uint8_t kNul = 0;
  hmac_sha256_update(&ctx, channel.size(), reinterpret_cast<const uint8_t*>(channel.data()));
  hmac_sha256_update(&ctx, 1, &kNul);
  hmac_sha256_update(&ctx, size, payload);
  hmac_sha256_update(&ctx, kHeadSize, head);
  hmac_sha256_digest(&ctx, kMacSize, out);
  explicit_bzero(&ctx, sizeof ctx);
}

void BusSigner::sign(std::string_view channel, uint8_t* payload, size_t size, const SignatureTrailer& trailer) const {
  uint8_t* head = payload + size;
  putBig(head, trailer.link, 4);
  putBig(head + 4, trailer.timestamp & 0xffff'ffff'ffffULL, 6);
  mac(channel, payload, size, head, head + kHeadSize);
}

bool BusSigner::verify(std::string_view channel, const uint8_t* data, size_t size) const {
  if (size < kSignatureSize) return false;
  const size_t payload = size - kSignatureSize;
  uint8_t expected[kMacSize];
  mac(channel, data, payload, data + payload, expected);
  return memeql_sec(expected, data + payload + kHeadSize, kMacSize) != 0;
}

SignatureTrailer trailerOf(const uint8_t* data, size_t size) {
  const uint8_t* head = data + size - kSignatureSize;
  return SignatureTrailer{static_cast<uint32_t>(getBig(head, 4)), getBig(head + 4, 6)};
}

RejectReason admitSigned(const BusSigner& signer, ReplayWindow& window, std::string_view channel,
                         const uint8_t* data, size_t size, bool fits_unsigned, uint64_t now) {
  if (size < kSignatureSize) return RejectReason::kUnsigned;
  if (!signer.verify(channel, data, size)) return fits_unsigned ? RejectReason::kUnsigned : RejectReason::kBadMac;
  const SignatureTrailer trailer = trailerOf(data, size);
  return window.offer(trailer.link, trailer.timestamp, now);
}

}  // namespace sdlqr::bus
