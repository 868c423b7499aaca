#pragma once
// The secret of a signed bus (signature.hpp): 32 bytes, read from a file that holds them as 64
// hexadecimal digits (one line). The file must be a regular file of mode 0600: a key others can
// read is refused, as ssh refuses a private key. Its bytes are never printed or logged, and the
// error texts name the file, never its contents.
// The file is named by the environment variable SDLQR_BUS_KEY (every process of a stack gets it
// from the launcher: docs/hosts-and-signing.md, Signed bus); one key per vehicle, so a vehicle's processes cannot
// sign for another vehicle on the same bus.

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace sdlqr::bus {

inline constexpr const char* kBusKeyVariable = "SDLQR_BUS_KEY";

struct BusKey {
  std::array<uint8_t, 32> bytes{};
  ~BusKey();  // wipes the bytes
};

// Throws std::invalid_argument with a one-line text naming `path` when the file is missing, not a
// regular file, of any mode but 0600 ("bus key F: mode 0644, must be 0600 (chmod 600 F)"), or not
// 64 hexadecimal digits.
BusKey loadBusKey(const std::string& path);

// The key named by SDLQR_BUS_KEY, or none when the variable is unset or empty (an unsigned bus).
std::optional<BusKey> busKeyFromEnvironment();

}  // namespace sdlqr::bus
