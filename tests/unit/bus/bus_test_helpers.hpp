#pragma once
// What the node tests share: they compile as one translation unit, so each helper is declared once.

#include <cstdint>
#include <string>

#include "sdlqr/bus/bus_key.hpp"
#include "sdlqr/bus/node.hpp"

namespace sdlqr::bus::test {

// An in-process bus (memq://), channels prefixed by `vehicle` when one is given.
inline ProcessOptions memq(const std::string& vehicle = "") {
  ProcessOptions options;
  options.lcm_url = "memq://";
  options.vehicle = vehicle;
  return options;
}

// A key whose 32 bytes are all `fill`.
inline BusKey keyOf(uint8_t fill) {
  BusKey key;
  key.bytes.fill(fill);
  return key;
}

}  // namespace sdlqr::bus::test
