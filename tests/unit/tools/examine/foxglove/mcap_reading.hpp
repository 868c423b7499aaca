#pragma once
// A small MCAP record reader for the writer's unit tests: enough to walk what McapWriter writes
// and check every offset, length and CRC it promises. (The integration tests read the same files
// with @mcap/core, an implementation nobody here wrote: tests/integration/view.)

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace sdlqr::foxglove::testing {

struct Cursor {
  std::string_view bytes;
  std::size_t pos = 0;

  uint64_t le(int n) {
    uint64_t v = 0;
    for (int i = 0; i < n; ++i) v |= static_cast<uint64_t>(static_cast<uint8_t>(bytes.at(pos + i))) << (8 * i);
    pos += n;
    return v;
  }
  uint8_t u8() { return static_cast<uint8_t>(le(1)); }
  uint16_t u16() { return static_cast<uint16_t>(le(2)); }
  uint32_t u32() { return static_cast<uint32_t>(le(4)); }
  uint64_t u64() { return le(8); }
  std::string_view take(std::size_t n) {
    const std::string_view s = bytes.substr(pos, n);
    pos += n;
    return s;
  }
  std::string str() { return std::string(take(u32())); }
  bool done() const { return pos >= bytes.size(); }
};

struct Record {
  uint8_t opcode = 0;
  std::size_t offset = 0;  // of the opcode, in the bytes walked
  std::string_view content;
};

// The records of a run of records (the data section, a chunk's records).
inline std::vector<Record> records(std::string_view bytes, std::size_t base = 0) {
  std::vector<Record> out;
  Cursor c{bytes};
  while (!c.done()) {
    Record r;
    r.offset = base + c.pos;
    r.opcode = c.u8();
    r.content = c.take(c.u64());
    out.push_back(r);
  }
  return out;
}

}  // namespace sdlqr::foxglove::testing
