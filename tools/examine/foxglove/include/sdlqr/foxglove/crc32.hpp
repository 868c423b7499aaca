#pragma once
// CRC-32 (ISO-HDLC: polynomial 0x04C11DB7 reflected, initial and final value 0xFFFFFFFF), the
// checksum of MCAP's chunks, data section and summary (mcap_writer.hpp). Incremental: feed the
// bytes in pieces, read value() at any point.

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace sdlqr::foxglove {

class Crc32 {
 public:
  void update(const void* data, std::size_t size);
  void update(std::string_view bytes) { update(bytes.data(), bytes.size()); }
  uint32_t value() const { return ~state_; }

 private:
  uint32_t state_ = 0xFFFFFFFFu;
};

inline uint32_t crc32(std::string_view bytes) {
  Crc32 crc;
  crc.update(bytes);
  return crc.value();
}

}  // namespace sdlqr::foxglove
