#pragma once
// MAVLink 2 frames, the receiving side: bytes in (a serial stream or UDP datagrams), checked frames
// out. Whatever arrives, it never reads out of bounds and never allocates; what it drops it counts
// by reason:
//   skipped bytes   before a start marker (garbage, line noise)
//   bad_flags       an incompat flag other than "signed": the frame's layout is unknown
//   bad_length      longer than its message's largest payload
//   bad_crc         checksum wrong (corrupted, or a different definition of the message)
//   unknown_id      a message this stack does not use (PX4 streams many: dropped, not an error);
//                   nothing proves it a frame, so its bytes are searched for the next marker
//   truncated       a datagram ended inside a frame
//   version1        an intact MAVLink 1 frame (0xFE) of a known message: PX4 speaks MAVLink 1 until
//                   it hears MAVLink 2 (MAV_PROTO_VER 0)
//   unsigned, bad_signature, replayed   with a key: signing.hpp
// Only a checksum proves a frame: after a bad header or checksum, or an unknown id, it resumes at
// the next start marker inside the bytes it had taken, so nothing unproven hides a good frame. Clock-free: `now` (the signing
// clock, signing.hpp) is passed in.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <cstdint>
#include <optional>

#include "sdlqr/mavlink/frame.hpp"
#include "sdlqr/mavlink/message_info.hpp"
#include "sdlqr/mavlink/signing.hpp"

namespace sdlqr::mavlink {

// A frame that passed every check; its payload zero-filled past `length` (truncation undone).
struct Frame {
  uint32_t id = 0;
  uint8_t seq = 0;
  Address source;
  uint8_t length = 0;      // [bytes] as received
  bool is_signed = false;  // checked against the key when the parser has one
  std::array<uint8_t, kMaxPayloadSize> payload{};

  template <class Message>
  Message as() const {
    Message message;
    message.decode(payload.data());
    return message;
  }
};

enum class FrameDrop : uint8_t {
  kBadFlags,
  kBadLength,
  kBadCrc,
  kUnknownId,
  kTruncated,
  kVersion1,
  kUnsigned,
  kBadSignature,
  kReplayed,
  kCount
};
inline constexpr size_t kFrameDropCount = static_cast<size_t>(FrameDrop::kCount);
const char* dropName(FrameDrop drop);  // "bad_crc", ...

struct ParserCounts {
  int64_t frames = 0;         // accepted
  int64_t skipped_bytes = 0;  // not part of any frame
  std::array<int64_t, kFrameDropCount> dropped{};
  int64_t droppedOf(FrameDrop d) const { return dropped[static_cast<size_t>(d)]; }
};

class Parser {
 public:
  // From now on only frames signed with `key` pass; without a key a signed frame passes unchecked
  // (as the specification allows a receiver that does not sign).
  void requireSigning(const SigningKey& key);
  bool signing() const { return key_.has_value(); }

  // Takes `size` bytes; calls on_frame(const Frame&) for each frame that passes.
  template <class OnFrame>
  void feed(const uint8_t* data, size_t size, uint64_t now, OnFrame&& on_frame) {
    while (size > 0) {
      // As many bytes as the frame begun needs (one when nothing is begun), then look at them.
      const size_t take = std::min(size, need_ - have_);
      std::memcpy(buffer_.data() + have_, data, take);
      have_ += take;
      data += take;
      size -= take;
      while (next(now)) on_frame(static_cast<const Frame&>(frame_));
    }
  }
  // The datagram that brought the last bytes ended: a frame begun in it is truncated (UDP
  // carries whole frames). Not called on a serial stream.
  void endDatagram();

  const ParserCounts& counts() const { return counts_; }

 private:
  // Looks at the buffered bytes: true when frame_ holds a new frame (and its bytes were consumed);
  // false when more bytes are needed (need_ says how many in all). Drops what cannot start a frame.
  bool next(uint64_t now);
  bool completeFrame(size_t total, const MessageInfo& info, uint64_t now);
  // The CRC of `count` bytes from `from` (plus the CRC extra) equals the two bytes after them.
  bool checksumMatches(size_t from, size_t count, const MessageInfo& info) const;
  void consume(size_t count);
  void drop(FrameDrop reason, size_t count);

  std::array<uint8_t, kMaxFrameSize> buffer_{};
  size_t have_ = 0;
  size_t need_ = 1;  // bytes next() needs buffered to get further: always > have_ after it
  Frame frame_;
  ParserCounts counts_;
  std::optional<SigningKey> key_;
  SignatureCheck signatures_;
};

}  // namespace sdlqr::mavlink
