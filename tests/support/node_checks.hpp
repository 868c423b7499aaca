#pragma once
// The two helpers of the single-binary checks over real multicast (bus_wire_check,
// signed_queue_check): a named check printed ok/FAIL and counted, and a node spun for a while.

#include <chrono>
#include <cstdio>
#include <string>

#include "sdlqr/bus/node.hpp"

namespace sdlqr::test {

// Checks failed so far; main returns it (0 when every check passed).
inline int& failedChecks() {
  static int failed = 0;
  return failed;
}

inline void check(bool ok, const std::string& what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAIL", what.c_str());
  if (!ok) ++failedChecks();
}

// Spins NODE (5 ms waits) for SECONDS of wall-clock time.
inline void spinFor(bus::Node& node, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) node.spin(5);
}

}  // namespace sdlqr::test
