#pragma once
// Bounds walking of an LCM encoding, used by the generated encodingFits() functions
// (sdlqr/lcmtypes/generated/wire_fits.hpp) before bytes are handed to an lcm-gen decoder.
// lcm-gen decoders resize their vectors to the array length in the message before checking
// that the bytes are there, so one corrupt length field (2^31 samples in a 60-byte event)
// would allocate and zero gigabytes. The walk reads only lengths and never allocates.

#include <cstdint>

namespace sdlqr::lcmtypes::wire {

struct Cursor {
  const uint8_t* data = nullptr;
  int64_t size = 0;
  int64_t pos = 0;

  bool skip(int64_t bytes) {
    if (bytes < 0 || bytes > size - pos) return false;
    pos += bytes;
    return true;
  }
  // Reads a big-endian signed integer of `bytes` bytes (1, 2, 4 or 8).
  bool readInteger(int bytes, int64_t* out) {
    if (bytes > size - pos) return false;
    uint64_t value = 0;
    for (int i = 0; i < bytes; ++i) value = (value << 8) | data[pos + i];
    const int shift = 64 - 8 * bytes;
    *out = shift > 0 ? static_cast<int64_t>(value << shift) >> shift : static_cast<int64_t>(value);
    pos += bytes;
    return true;
  }
  // An LCM string: int32 length including the terminating NUL, then the bytes.
  bool skipString() {
    int64_t length = 0;
    return readInteger(4, &length) && length >= 1 && skip(length);
  }
  // `count` elements of at least `min_bytes` each fit in what is left.
  bool fits(int64_t count, int64_t min_bytes) const { return count >= 0 && count <= (size - pos) / min_bytes; }
};

// Product of array dimensions, false if a factor is negative or the product cannot fit.
inline bool elementCount(int64_t a, int64_t b, int64_t limit, int64_t* out) {
  if (a < 0 || b < 0 || (a > 0 && b > limit / a)) return false;
  *out = a * b;
  return true;
}

}  // namespace sdlqr::lcmtypes::wire
