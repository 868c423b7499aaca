#include "sdlqr/mavlink/frame.hpp"

#include <cstring>

#include "sdlqr/mavlink/crc.hpp"

namespace sdlqr::mavlink {

size_t truncatedLength(const uint8_t* payload, size_t max_length) {
  size_t length = max_length;
  while (length > 1 && payload[length - 1] == 0) --length;
  return length;
}

void FrameWriter::enableSigning(const SigningKey& key, uint8_t link_id) {
  key_.emplace();
  key_->bytes = key.bytes;
  link_id_ = link_id;
}

size_t FrameWriter::writeFrame(uint32_t id, uint8_t crc_extra, const uint8_t* payload, size_t max_length,
                               uint64_t signing_time, uint8_t* out) {
  const size_t length = truncatedLength(payload, max_length);
  out[0] = kStartMarker;
  out[1] = static_cast<uint8_t>(length);
  out[2] = key_ ? kIncompatSigned : 0;
  out[3] = 0;
  out[4] = seq_++;
  out[5] = self_.system;
  out[6] = self_.component;
  out[7] = static_cast<uint8_t>(id & 0xFF);
  out[8] = static_cast<uint8_t>((id >> 8) & 0xFF);
  out[9] = static_cast<uint8_t>((id >> 16) & 0xFF);
  std::memcpy(out + kHeaderSize, payload, length);
  uint16_t crc = crcAccumulate(out + 1, kHeaderSize - 1 + length, kCrcInit);
  crc = crcAccumulate(crc_extra, crc);
  uint8_t* p = out + kHeaderSize + length;
  p[0] = static_cast<uint8_t>(crc & 0xFF);
  p[1] = static_cast<uint8_t>(crc >> 8);
  size_t size = kHeaderSize + length + kChecksumSize;
  if (!key_) return size;
  last_timestamp_ = signing_time > last_timestamp_ ? signing_time : last_timestamp_ + 1;
  p += kChecksumSize;
  p[0] = link_id_;
  for (int i = 0; i < 6; ++i) p[1 + i] = static_cast<uint8_t>(last_timestamp_ >> (8 * i));
  const auto signature = signatureOf(*key_, out, size + 7);
  std::memcpy(p + 7, signature.data(), signature.size());
  return size + kSignatureSize;
}

}  // namespace sdlqr::mavlink
