// libFuzzer harness of what sdlqr-px4 does with bytes from its MAVLink link: the parser as a UDP
// datagram and as a serial stream, then the bridge's core (frames, signatures, conversions,
// validation, the handshake). Input: one selector byte (bit 0: stream, bit 1: the parser requires a
// signature, bit 2: through the bridge), then the bytes. Beyond ASan/UBSan findings it checks one
// property: every frame the parser accepts, written again by our writer, parses to the same
// message id and payload.

#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "sdlqr/mavlink/parser.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/px4/bridge_core.hpp"

namespace {

using namespace sdlqr;


void rewriteAndCompare(const mavlink::Frame& f) {
  const mavlink::MessageInfo* info = mavlink::findMessage(f.id);
  if (info == nullptr) std::abort();  // the parser accepted an id it cannot know
  mavlink::FrameWriter writer(f.source);
  uint8_t bytes[mavlink::kMaxFrameSize];
  const size_t size = writer.writeFrame(f.id, info->crc_extra, f.payload.data(), info->max_length, 0, bytes);
  mavlink::Parser again;
  bool same = false;
  again.feed(bytes, size, 0, [&](const mavlink::Frame& g) {
    same = g.id == f.id && std::memcmp(g.payload.data(), f.payload.data(), info->max_length) == 0;
  });
  if (!same) std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 1) return 0;
  const uint8_t selector = data[0];
  ++data;
  --size;
  static mavlink::SigningKey key;  // all zero: a fuzzer may well find it, which is fine here
  if ((selector & 4) == 0) {
    mavlink::Parser parser;
    if (selector & 2) parser.requireSigning(key);
    if (selector & 1) {
      for (size_t at = 0; at < size; at += 7) parser.feed(data + at, std::min<size_t>(7, size - at), 0, rewriteAndCompare);
    } else {
      parser.feed(data, size, 0, rewriteAndCompare);
      parser.endDatagram();
    }
    return 0;
  }
  static px4::DiscardingSink sink;
  static px4::MavlinkEndpoint endpoint({1, px4::kOnboardComputerComponent}, sink, [] { return uint64_t{0}; });
  static px4::BridgeCore bridge(px4::BridgeParams(), 9.81, ValidationLimits(), endpoint);
  static OutboxTo<NoObserver> bus{NoObserver{}};
  static double now = 0.0;
  now += 0.01;
  bridge.onWallTime(now);
  bridge.onBytes(data, size, (selector & 1) == 0, bus);
  return 0;
}
