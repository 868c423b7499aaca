// The parser of LCM's UDP multicast datagrams (common/bus/src/udpm_inbox.hpp) on hand-built
// packets: what it accepts, what it refuses. Real LCM packets: integration test bus_wire_check.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "udpm_inbox.hpp"

namespace sdlqr::bus {
namespace {

void put32(std::vector<uint8_t>& out, uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<uint8_t>(v >> shift));
}
void put16(std::vector<uint8_t>& out, uint16_t v) {
  out.push_back(static_cast<uint8_t>(v >> 8));
  out.push_back(static_cast<uint8_t>(v));
}

std::vector<uint8_t> shortPacket(const std::string& channel, const std::vector<uint8_t>& payload) {
  std::vector<uint8_t> p;
  put32(p, 0x4c433032);
  put32(p, 7);
  p.insert(p.end(), channel.begin(), channel.end());
  p.push_back(0);
  p.insert(p.end(), payload.begin(), payload.end());
  return p;
}

// Fragment `number` of `count` of a message of `total` bytes; fragment 0 carries the channel.
std::vector<uint8_t> fragment(uint32_t sequence, uint32_t total, uint32_t offset, uint16_t number, uint16_t count,
                              const std::string& channel, const std::vector<uint8_t>& data) {
  std::vector<uint8_t> p;
  put32(p, 0x4c433033);
  put32(p, sequence);
  put32(p, total);
  put32(p, offset);
  put16(p, number);
  put16(p, count);
  if (number == 0) {
    p.insert(p.end(), channel.begin(), channel.end());
    p.push_back(0);
  }
  p.insert(p.end(), data.begin(), data.end());
  return p;
}

TEST(UdpmWire, ShortMessageGivesChannelAndPayload) {
  const std::vector<uint8_t> p = shortPacket("QUAD1/IMU", {9, 0, 8});
  WireMessage m;
  ASSERT_TRUE(parseShortMessage(p.data(), p.size(), &m));
  EXPECT_EQ(m.channel, "QUAD1/IMU");
  ASSERT_EQ(m.size, 3u);
  EXPECT_EQ(m.data[0], 9);
  EXPECT_EQ(m.data[2], 8);
}

TEST(UdpmWire, MalformedShortMessagesAreRefused) {
  WireMessage m;
  std::vector<uint8_t> p = shortPacket("IMU", {1});
  p[0] = 'X';  // not LCM
  EXPECT_FALSE(parseShortMessage(p.data(), p.size(), &m));
  p = shortPacket("IMU", {});
  p.pop_back();  // no NUL after the channel
  EXPECT_FALSE(parseShortMessage(p.data(), p.size(), &m));
  p = shortPacket(std::string(64, 'A'), {1});  // channel longer than LCM's 63
  EXPECT_FALSE(parseShortMessage(p.data(), p.size(), &m));
  p = shortPacket("", {1});  // empty channel
  EXPECT_FALSE(parseShortMessage(p.data(), p.size(), &m));
  EXPECT_FALSE(parseShortMessage(p.data(), 5, &m));  // shorter than the header
}

TEST(UdpmWire, FragmentsReassembleInOrderPerSender) {
  FragmentAssembler assembler;
  const std::vector<uint8_t> a{1, 2, 3, 4}, b{5, 6};
  const auto f0 = fragment(3, 6, 0, 0, 2, "BIG", a);
  const auto f1 = fragment(3, 6, 4, 1, 2, "BIG", b);
  // Another sender's fragment in between does not disturb the first.
  const auto other = fragment(9, 2, 0, 0, 2, "OTHER", {7});
  EXPECT_FALSE(assembler.add(1, f0.data(), f0.size()));
  EXPECT_FALSE(assembler.add(2, other.data(), other.size()));
  ASSERT_TRUE(assembler.add(1, f1.data(), f1.size()));
  EXPECT_EQ(assembler.channel(), "BIG");
  EXPECT_EQ(assembler.data(), (std::vector<uint8_t>{1, 2, 3, 4, 5, 6}));
}

TEST(UdpmWire, BrokenFragmentSequencesAreDropped) {
  FragmentAssembler assembler;
  // A later fragment without its first one.
  const auto lone = fragment(3, 6, 4, 1, 2, "BIG", {5, 6});
  EXPECT_FALSE(assembler.add(1, lone.data(), lone.size()));
  // A fragment of another message (new sequence) replaces the one in progress.
  const auto f0 = fragment(3, 6, 0, 0, 2, "BIG", {1, 2, 3, 4});
  const auto g1 = fragment(4, 6, 4, 1, 2, "BIG", {5, 6});
  EXPECT_FALSE(assembler.add(1, f0.data(), f0.size()));
  EXPECT_FALSE(assembler.add(1, g1.data(), g1.size()));
  // Data past the announced size.
  const auto h0 = fragment(5, 4, 0, 0, 2, "BIG", {1, 2});
  const auto h1 = fragment(5, 4, 2, 1, 2, "BIG", {3, 4, 5});
  EXPECT_FALSE(assembler.add(1, h0.data(), h0.size()));
  EXPECT_FALSE(assembler.add(1, h1.data(), h1.size()));
  // Fragment number past the count, and a short message offered as a fragment.
  const auto bad = fragment(6, 2, 0, 2, 2, "BIG", {1, 2});
  EXPECT_FALSE(assembler.add(1, bad.data(), bad.size()));
  const auto plain = shortPacket("IMU", {1});
  EXPECT_FALSE(assembler.add(1, plain.data(), plain.size()));
}

}  // namespace
}  // namespace sdlqr::bus
