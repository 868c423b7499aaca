#pragma once
// MAVLink 2 frames (mavlink.io/en/guide/serialization.html), the sending side:
//
//   0xFD len incompat compat seq sysid compid msgid(3 bytes, little-endian) | payload (len bytes)
//   | CRC (2 bytes, little-endian) [| link id, timestamp (6), signature (6): signing.hpp]
//
// The payload is the message's fields in wire order with its trailing zero bytes cut, at least
// one byte kept (the reference C library's _mav_trim_payload); the CRC is X.25 over the frame
// from `len` through the payload, then the message's CRC extra. incompat bit 0 marks a signed
// frame, the only flag MAVLink 2 defines. Pure and clock-free: the signing clock is passed in.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "sdlqr/mavlink/signing.hpp"

namespace sdlqr::mavlink {

inline constexpr uint8_t kStartMarker = 0xFD;    // MAVLink 2
inline constexpr uint8_t kStartMarkerV1 = 0xFE;  // MAVLink 1: recognised, counted, never decoded
inline constexpr size_t kHeaderSize = 10;
inline constexpr size_t kHeaderSizeV1 = 6;
inline constexpr size_t kChecksumSize = 2;
inline constexpr size_t kSignatureSize = 13;
inline constexpr size_t kMaxPayloadSize = 255;
inline constexpr size_t kMaxFrameSize = kHeaderSize + kMaxPayloadSize + kChecksumSize + kSignatureSize;
inline constexpr uint8_t kIncompatSigned = 0x01;

struct Address {
  uint8_t system = 0;
  uint8_t component = 0;
};

// The payload length after MAVLink 2's truncation of trailing zero bytes (at least 1).
size_t truncatedLength(const uint8_t* payload, size_t max_length);

// Frames the messages of one sender: its address, its sequence number, its signing (optional).
class FrameWriter {
 public:
  explicit FrameWriter(Address self) : self_(self) {}
  // From now on every frame is signed with `key` on link `link_id`.
  void enableSigning(const SigningKey& key, uint8_t link_id);
  bool signing() const { return key_.has_value(); }

  // Writes `message` as one frame into `out` (kMaxFrameSize bytes) and returns its size.
  // `signing_time`: signing.hpp's clock, used when signing (a frame's timestamp is the later of it
  // and the previous frame's plus one, as the specification requires).
  template <class Message>
  size_t write(const Message& message, uint64_t signing_time, uint8_t* out) {
    uint8_t payload[Message::kMaxLength];
    message.encode(payload);
    return writeFrame(Message::kId, Message::kCrcExtra, payload, Message::kMaxLength, signing_time, out);
  }
  size_t writeFrame(uint32_t id, uint8_t crc_extra, const uint8_t* payload, size_t max_length, uint64_t signing_time,
                    uint8_t* out);
  Address address() const { return self_; }

 private:
  Address self_;
  uint8_t seq_ = 0;
  std::optional<SigningKey> key_;
  uint8_t link_id_ = 0;
  uint64_t last_timestamp_ = 0;
};

}  // namespace sdlqr::mavlink
