// A signed bus through the Node over memq:// (common/bus node.hpp, "Signed bus"): nodes with the
// key hear each other; a node without it, a node with another key and a replayed message are
// rejected on arrival, counted per stream and reason in the HEARTBEAT counters, and never reach
// the handler; a node without a key still decodes signed messages (as a log reader does); and
// signing allocates nothing per message once running.

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"
#include "bus_test_helpers.hpp"

namespace sdlqr::bus {
namespace {

using test::keyOf;
using test::memq;

rate_cmd_t command(int64_t seq) {
  RateCommand c;
  c.utime = seq * 10000;
  c.seq = seq;
  c.thrust = 9.0;
  return toLcm(c);
}

// Handles every message waiting (memq:// hands over one per call).
void handleAll(Node& node) {
  while (node.lcm().handleTimeout(0) > 0) {
  }
}

// The LCM encoding of a command, with room for a signature trailer after it when `trailer`.
std::vector<uint8_t> encoded(const rate_cmd_t& message, bool trailer = false) {
  std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()) + (trailer ? kSignatureSize : 0));
  message.encode(bytes.data(), 0, message.getEncodedSize());
  return bytes;
}

// A memq bus is one Node's own: it hears what it publishes, and what is published on its LCM.
struct Receiver {
  Receiver() : node("lowlevel", memq("QUAD")) {
    node.subscribe<rate_cmd_t>(channel::kRateCommand, [&](const rate_cmd_t& m) { handled.push_back(m.seq); }, 64);
  }
  explicit Receiver(const BusKey& key) : Receiver() { node.setBusKey(key); }

  // Bytes on QUAD/RATE_CMD straight from LCM, as a process that is not a Node would send them.
  void publishRaw(const std::vector<uint8_t>& bytes) {
    node.lcm().publish("QUAD/RATE_CMD", bytes.data(), static_cast<unsigned>(bytes.size()));
  }

  Node node;
  std::vector<int64_t> handled;
};

TEST(NodeSigning, SignedMessagesReachTheHandlerWithTheirPayload) {
  Receiver r(keyOf(1));
  r.node.publish(channel::kRateCommand, command(1));
  r.node.publish(channel::kRateCommand, command(2));
  handleAll(r.node);
  EXPECT_EQ(r.handled, (std::vector<int64_t>{1, 2}));
  EXPECT_EQ(r.node.rejected(), 0);
}

TEST(NodeSigning, UnsignedAndForgedMessagesAreRejectedAndCountedByReason) {
  Receiver r(keyOf(1));
  // Unsigned: a well-formed command published by LCM directly (a process without the key).
  std::vector<uint8_t> bytes = encoded(command(5));
  r.publishRaw(bytes);
  // Forged: signed, with another key.
  BusSigner other(keyOf(2));
  bytes.resize(bytes.size() + kSignatureSize);
  other.sign("QUAD/RATE_CMD", bytes.data(), bytes.size() - kSignatureSize, {42, signatureTime(1'800'000'000'000'000)});
  r.publishRaw(bytes);
  handleAll(r.node);
  EXPECT_TRUE(r.handled.empty());
  EXPECT_EQ(r.node.health().counter("reject.rate_cmd.unsigned"), 1);
  EXPECT_EQ(r.node.health().counter("reject.rate_cmd.bad_mac"), 1);
  EXPECT_EQ(r.node.health().counter("reject.unsigned"), 1);
  EXPECT_EQ(r.node.rejected(), 2);
}

TEST(NodeSigning, AReplayedSignedMessageIsRejected) {
  Receiver r(keyOf(1));
  std::vector<uint8_t> recorded;
  r.node.subscribeRaw("QUAD/RATE_CMD", [&](const std::string&, const void* data, uint32_t size, int64_t) {
    if (recorded.empty()) recorded.assign(static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
  }, 64);
  r.node.publish(channel::kRateCommand, command(1));
  handleAll(r.node);
  ASSERT_EQ(r.handled, (std::vector<int64_t>{1}));
  // The recorder got the bytes as sent: the trailer included.
  EXPECT_EQ(recorded.size(), static_cast<size_t>(command(1).getEncodedSize()) + kSignatureSize);
  // The same bytes again (a capture sent back without the key):
  r.publishRaw(recorded);
  handleAll(r.node);
  EXPECT_EQ(r.handled, (std::vector<int64_t>{1}));
  EXPECT_EQ(r.node.health().counter("reject.rate_cmd.replayed"), 1);
}

TEST(NodeSigning, WithoutAKeyTheSameInjectionIsHandled) {
  // The negative of the two tests above: an unsigned subscriber takes the unsigned command.
  Receiver r;
  const std::vector<uint8_t> bytes = encoded(command(5));
  r.publishRaw(bytes);
  handleAll(r.node);
  EXPECT_EQ(r.handled, (std::vector<int64_t>{5}));
  EXPECT_EQ(r.node.rejected(), 0);
}

TEST(NodeSigning, ANodeWithoutTheKeyStillDecodesSignedMessages) {
  Receiver r;  // no key: decodes what a signed publisher sends (its trailer ignored)
  std::vector<uint8_t> bytes = encoded(command(3), true);
  BusSigner(keyOf(1)).sign("QUAD/RATE_CMD", bytes.data(), bytes.size() - kSignatureSize, {1, 1});
  r.publishRaw(bytes);
  handleAll(r.node);
  EXPECT_EQ(r.handled, (std::vector<int64_t>{3}));
}

TEST(NodeSigning, ABridgeForwardsBytesAsHeardAndSignsForNobody) {
  Receiver r(keyOf(1));
  std::vector<uint8_t> bytes = encoded(command(5));
  // A forwarded unsigned message stays unsigned (a bridge with the key launders nothing) ...
  r.node.forwardEncoded("QUAD/RATE_CMD", bytes.data(), static_cast<int>(bytes.size()));
  handleAll(r.node);
  EXPECT_TRUE(r.handled.empty());
  EXPECT_EQ(r.node.health().counter("reject.rate_cmd.unsigned"), 1);
  // ... a forwarded signed one keeps its signature, and a tool's own encoded bytes are signed.
  bytes.resize(bytes.size() + kSignatureSize);
  BusSigner(keyOf(1)).sign("QUAD/RATE_CMD", bytes.data(), bytes.size() - kSignatureSize,
                           {9, signatureTime(std::chrono::duration_cast<std::chrono::microseconds>(
                                   std::chrono::system_clock::now().time_since_epoch()).count())});
  r.node.forwardEncoded("QUAD/RATE_CMD", bytes.data(), static_cast<int>(bytes.size()));
  const std::vector<uint8_t> own_bytes = encoded(command(6));
  r.node.publishEncoded("QUAD/RATE_CMD", own_bytes.data(), static_cast<int>(own_bytes.size()));
  handleAll(r.node);
  EXPECT_EQ(r.handled, (std::vector<int64_t>{5, 6}));
  EXPECT_EQ(r.node.rejected(), 1);
}

TEST(NodeSigning, SigningAndCheckingAllocateNothingOnceRunning) {
  Receiver r(keyOf(1));
  for (int64_t seq = 0; seq < 10; ++seq) {  // warm-up: channel names, heartbeat, buffers
    r.node.publish(channel::kRateCommand, command(seq));
    handleAll(r.node);
  }
  r.handled.reserve(2000);
  rate_cmd_t message = command(0);
  const long before = sdlqr::testing::allocationCount();
  for (int64_t seq = 10; seq < 1010; ++seq) {
    message.seq = seq;
    r.node.publish(channel::kRateCommand, message);
    while (r.node.lcm().handleTimeout(0) > 0) {
    }
  }
  EXPECT_EQ(sdlqr::testing::allocationCount() - before, 0);
  EXPECT_EQ(r.handled.back(), 1009);
  EXPECT_EQ(r.node.rejected(), 0);
}

}  // namespace
}  // namespace sdlqr::bus
