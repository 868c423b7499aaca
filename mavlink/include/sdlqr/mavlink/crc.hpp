#pragma once
// The checksum of a MAVLink frame: X.25, also named CRC-16/MCRF4XX (initial value 0xFFFF,
// reflected polynomial 0x1021, no final XOR), computed as the reference C library's
// crc_accumulate (mavlink/c_library_v2 checksum.h). A frame's CRC covers the bytes after the
// start marker through the payload, then the message's CRC extra byte. Header-only: the
// generator (mavlink/gen) computes each message's CRC extra with the same function.

#include <cstddef>
#include <cstdint>

namespace sdlqr::mavlink {

inline constexpr uint16_t kCrcInit = 0xFFFF;

constexpr uint16_t crcAccumulate(uint8_t byte, uint16_t crc) {
  uint8_t tmp = static_cast<uint8_t>(byte ^ static_cast<uint8_t>(crc & 0xFF));
  tmp = static_cast<uint8_t>(tmp ^ static_cast<uint8_t>(tmp << 4));
  return static_cast<uint16_t>((crc >> 8) ^ (static_cast<uint16_t>(tmp) << 8) ^ (static_cast<uint16_t>(tmp) << 3) ^
                               (tmp >> 4));
}

constexpr uint16_t crcAccumulate(const uint8_t* bytes, size_t size, uint16_t crc) {
  for (size_t i = 0; i < size; ++i) crc = crcAccumulate(bytes[i], crc);
  return crc;
}

}  // namespace sdlqr::mavlink
