#include "sdlqr/mavlink/parser.hpp"

#include <cstring>

#include "sdlqr/mavlink/crc.hpp"

namespace sdlqr::mavlink {

const char* dropName(FrameDrop drop) {
  switch (drop) {
    case FrameDrop::kBadFlags: return "bad_flags";
    case FrameDrop::kBadLength: return "bad_length";
    case FrameDrop::kBadCrc: return "bad_crc";
    case FrameDrop::kUnknownId: return "unknown_id";
    case FrameDrop::kTruncated: return "truncated";
    case FrameDrop::kVersion1: return "version1";
    case FrameDrop::kUnsigned: return "unsigned";
    case FrameDrop::kBadSignature: return "bad_signature";
    case FrameDrop::kReplayed: return "replayed";
    case FrameDrop::kCount: break;
  }
  return "unknown";
}

void Parser::requireSigning(const SigningKey& key) {
  key_.emplace();
  key_->bytes = key.bytes;
}

void Parser::consume(size_t count) {
  std::memmove(buffer_.data(), buffer_.data() + count, have_ - count);
  have_ -= count;
}

void Parser::drop(FrameDrop reason, size_t count) {
  ++counts_.dropped[static_cast<size_t>(reason)];
  consume(count);
}

void Parser::endDatagram() {
  if (have_ == 0) return;
  drop(FrameDrop::kTruncated, have_);
  need_ = 1;
}

bool Parser::next(uint64_t now) {
  const auto wait_for = [this](size_t bytes) {
    need_ = bytes;
    return false;
  };
  while (have_ > 0) {
    const uint8_t marker = buffer_[0];
    if (marker != kStartMarker && marker != kStartMarkerV1) {
      ++counts_.skipped_bytes;
      consume(1);
      continue;
    }
    if (marker == kStartMarkerV1) {
      if (have_ < kHeaderSizeV1) return wait_for(kHeaderSizeV1);
      const MessageInfo* info = findMessage(buffer_[5]);
      if (info == nullptr || buffer_[1] > info->max_length) {
        ++counts_.skipped_bytes;
        consume(1);
        continue;
      }
      const size_t total = kHeaderSizeV1 + buffer_[1] + kChecksumSize;
      if (have_ < total) return wait_for(total);
      const bool intact = checksumMatches(1, kHeaderSizeV1 - 1 + buffer_[1], *info);
      if (intact) {
        drop(FrameDrop::kVersion1, total);
      } else {
        ++counts_.skipped_bytes;
        consume(1);
      }
      continue;
    }
    if (have_ < kHeaderSize) return wait_for(kHeaderSize);
    const uint8_t length = buffer_[1];
    const uint8_t incompat = buffer_[2];
    if ((incompat & ~kIncompatSigned) != 0) {
      drop(FrameDrop::kBadFlags, 1);  // resynchronise on the next marker
      continue;
    }
    const uint32_t id = buffer_[7] | (static_cast<uint32_t>(buffer_[8]) << 8) | (static_cast<uint32_t>(buffer_[9]) << 16);
    const MessageInfo* info = findMessage(id);
    if (info != nullptr && length > info->max_length) {
      drop(FrameDrop::kBadLength, 1);
      continue;
    }
    if (info == nullptr) {
      // A message this stack does not use, or garbage: without its CRC extra nothing proves it a
      // frame, so it costs one byte and the rest is searched for the next marker.
      drop(FrameDrop::kUnknownId, 1);
      continue;
    }
    const size_t total = kHeaderSize + length + kChecksumSize + ((incompat & kIncompatSigned) ? kSignatureSize : 0);
    if (have_ < total) return wait_for(total);
    if (completeFrame(total, *info, now)) return true;
  }
  return wait_for(1);
}

bool Parser::checksumMatches(size_t from, size_t count, const MessageInfo& info) const {
  uint16_t crc = crcAccumulate(buffer_.data() + from, count, kCrcInit);
  crc = crcAccumulate(info.crc_extra, crc);
  const uint8_t* sent = buffer_.data() + from + count;
  return sent[0] == (crc & 0xFF) && sent[1] == (crc >> 8);
}

bool Parser::completeFrame(size_t total, const MessageInfo& info, uint64_t now) {
  const uint8_t length = buffer_[1];
  if (!checksumMatches(1, kHeaderSize - 1 + length, info)) {
    drop(FrameDrop::kBadCrc, 1);
    return false;
  }
  const bool is_signed = (buffer_[2] & kIncompatSigned) != 0;
  if (key_) {
    if (!is_signed) {
      drop(FrameDrop::kUnsigned, total);
      return false;
    }
    const SignatureVerdict verdict = signatures_.check(*key_, buffer_.data(), total, buffer_[5], buffer_[6], now);
    if (verdict != SignatureVerdict::kAccepted) {
      drop(verdict == SignatureVerdict::kReplayed ? FrameDrop::kReplayed : FrameDrop::kBadSignature, total);
      return false;
    }
  }
  frame_.id = info.id;
  frame_.seq = buffer_[4];
  frame_.source = Address{buffer_[5], buffer_[6]};
  frame_.length = length;
  frame_.is_signed = is_signed;
  std::memcpy(frame_.payload.data(), buffer_.data() + kHeaderSize, length);
  std::memset(frame_.payload.data() + length, 0, kMaxPayloadSize - length);
  ++counts_.frames;
  consume(total);
  return true;
}

}  // namespace sdlqr::mavlink
