#pragma once
// A MAVLink link beside the bus in a main: the node polls the link's descriptor in its own loop
// (bus::Node::watchDescriptor), each datagram or serial read goes to the core, and on udp:// the
// sender of a datagram that held an accepted frame becomes the peer answered.

#include <stdexcept>

#include "sdlqr/bus/node.hpp"
#include "sdlqr/px4/link_io.hpp"
#include "sdlqr/px4/mavlink_endpoint.hpp"

namespace sdlqr::px4 {

// on_bytes(data, size, datagram) hands the bytes to the core (which parses them through `endpoint`).
template <class OnBytes>
void bindLink(bus::Node& node, LinkIo& io, const MavlinkEndpoint& endpoint, OnBytes on_bytes) {
  node.watchDescriptor(io.fd(), [&node, &io, &endpoint, on_bytes]() {
    const int reads = io.readReady([&](const uint8_t* data, size_t size) {
      const int64_t before = endpoint.received().frames;
      on_bytes(data, size, io.datagrams());
      if (endpoint.received().frames > before) io.acceptLastSender();
    });
    if (reads < 0) {
      node.setLastError("MAVLink link failed: " + io.describe());
      throw std::runtime_error("MAVLink link failed: " + io.describe());
    }
  });
}

}  // namespace sdlqr::px4
