#pragma once
// The command lines of sdlqr-px4 (the bridge) and sdlqr-px4-emulator, and what both mains share:
// the MAVLink signing key (the bus key's file rules: 64 hex digits, mode 0600; SECURITY.md) and
// the wall-clock signing time.

#include <cstdint>
#include <optional>
#include <string>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/mavlink/signing.hpp"

namespace sdlqr::px4 {

inline constexpr const char* kMavlinkKeyVariable = "SDLQR_MAVLINK_KEY";

struct LinkOptions {
  std::string mavlink_url;
  std::string key_path;  // empty: $SDLQR_MAVLINK_KEY, else an unsigned link
  int link_id = 0;
};

struct BridgeCommandLine {
  ProcessOptions process;
  LinkOptions link;
  bool bench = false;
  bool clock_from_start = false;  // --clock start
  std::string identify_log;  // --identify-hover LOG: fit the hover throttle and exit
};

struct EmulatorCommandLine {
  ProcessOptions process;
  LinkOptions link;
  std::string scenario_path;
  long long seed = -1;
  double rate = 1.0;
};

// Exit 0 on --help, 2 on a bad option (ArgParser).
BridgeCommandLine parseBridgeCommandLine(int argc, const char* const* argv);
EmulatorCommandLine parseEmulatorCommandLine(int argc, const char* const* argv);

// The key of --mavlink-key, else of $SDLQR_MAVLINK_KEY, else none. Throws std::invalid_argument
// naming the file (never its contents) when it is unreadable, of a mode other than 0600 or no key.
std::optional<mavlink::SigningKey> loadLinkKey(const LinkOptions& options);
// The signing clock now (signing.hpp) from the system clock.
uint64_t wallSigningTime();

}  // namespace sdlqr::px4
