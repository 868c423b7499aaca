#pragma once
// Hostile variants of a valid LCM encoding, for the fuzz publisher and the bus fault tests. Pure:
// bytes in, bytes out, a seeded generator; no LCM, no clock.

#include <cstdint>
#include <random>
#include <string_view>
#include <vector>

#include "sdlqr/lcmtypes/field_descriptor.hpp"

namespace sdlqr::faults {

enum class FuzzKind : int {
  kRandomBytes = 0,   // random length (1..2x the valid size), random content
  kTruncated,         // a valid encoding cut short
  kOversized,         // a valid encoding with random bytes appended
  kWrongFingerprint,  // the right size, a different type hash
  kNonFinite,         // a valid encoding with one double field set to NaN, +Inf or -Inf
  kHuge,              // a valid encoding with one double field set to +-1e300 or +-1e12
  kReplayed,          // an encoding seen on the bus a while ago, sent again unchanged
};
inline constexpr int kFuzzKindCount = 7;
const char* toString(FuzzKind kind);

// Byte offsets of every double (scalar or array element) in a valid encoding of `type`, walking
// the descriptor's fields after the 8-byte fingerprint. Empty when the walk does not fit `size`.
std::vector<int64_t> doubleOffsets(const lcmtypes::TypeDescriptor& type, const uint8_t* data, int64_t size);

class FuzzGenerator {
 public:
  explicit FuzzGenerator(uint64_t seed) : rng_(seed) {}
  // Writes into `out` the variant `kind` of `valid` (an encoding of `type`; for kReplayed pass
  // the old encoding as `valid`). Returns false when the kind cannot be made from it (no double
  // field for kNonFinite/kHuge): nothing to send.
  bool make(FuzzKind kind, const lcmtypes::TypeDescriptor& type, const std::vector<uint8_t>& valid,
            std::vector<uint8_t>& out);

 private:
  uint64_t next() { return rng_(); }
  std::mt19937_64 rng_;
};

}  // namespace sdlqr::faults
