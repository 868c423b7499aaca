// The receiving side: every message round-trips through frame and parser; bad input of every
// kind is counted by its reason and dropped, never crashes and never hides a good frame after
// it; a stream fed a byte at a time parses as whole datagrams do.

#include <gtest/gtest.h>

#include <random>

#include "mavlink_test_support.hpp"
#include "sdlqr/mavlink/crc.hpp"

namespace sdlqr::mavlink {
namespace {

using test::frameOf;
using test::parseAll;

TEST(MavlinkParser, EveryMessageRoundTrips) {
  FrameWriter writer(Address{1, 1});
  Parser parser;
  const Odometry odometry = test::sampleOdometry();
  const auto frames = parseAll(parser, frameOf(writer, odometry));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].id, Odometry::kId);
  EXPECT_EQ(frames[0].length, 232);
  const Odometry back = frames[0].as<Odometry>();
  EXPECT_EQ(back.time_usec, odometry.time_usec);
  EXPECT_EQ(back.q, odometry.q);
  EXPECT_EQ(back.velocity_covariance, odometry.velocity_covariance);
  EXPECT_EQ(back.estimator_type, odometry.estimator_type);
  EXPECT_EQ(back.quality, 0);
  // One of each generated message, its every field compared through the generated visit.
  std::apply(
      [&](auto... messages) {
        auto check = [&](auto message) {
          int k = 1;
          message.visitFields([&k](const char*, auto& field) {
            if constexpr (std::is_arithmetic_v<std::decay_t<decltype(field)>>) {
              field = static_cast<std::decay_t<decltype(field)>>(k++);
            } else {
              for (auto& element : field) element = static_cast<std::decay_t<decltype(element)>>(k++);
            }
          });
          const auto parsed = parseAll(parser, frameOf(writer, message));
          ASSERT_EQ(parsed.size(), 1u) << decltype(message)::kName;
          const auto back = parsed[0].template as<decltype(message)>();
          std::vector<double> sent, received;
          message.visitFields([&](const char*, const auto& f) {
            if constexpr (std::is_arithmetic_v<std::decay_t<decltype(f)>>) sent.push_back(static_cast<double>(f));
            else for (auto e : f) sent.push_back(static_cast<double>(e));
          });
          back.visitFields([&](const char*, const auto& f) {
            if constexpr (std::is_arithmetic_v<std::decay_t<decltype(f)>>) received.push_back(static_cast<double>(f));
            else for (auto e : f) received.push_back(static_cast<double>(e));
          });
          EXPECT_EQ(sent, received) << decltype(message)::kName;
        };
        (check(messages), ...);
      },
      AllMessages{});
  EXPECT_EQ(parser.counts().frames, 1 + static_cast<int64_t>(std::tuple_size_v<AllMessages>));
}

TEST(MavlinkParser, ATruncatedDatagramIsCountedAndDropped) {
  FrameWriter writer(Address{1, 1});
  Parser parser;
  auto bytes = frameOf(writer, test::sampleOdometry());
  bytes.resize(bytes.size() - 5);
  EXPECT_TRUE(parseAll(parser, bytes).empty());
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kTruncated), 1);
  // The next datagram parses: nothing of the cut frame is left over.
  EXPECT_EQ(parseAll(parser, frameOf(writer, test::sampleSetpoint())).size(), 1u);
}

TEST(MavlinkParser, AWrongChecksumIsCountedAndTheNextFrameStillParses) {
  FrameWriter writer(Address{1, 1});
  Parser parser;
  auto bad = frameOf(writer, test::sampleSetpoint());
  bad[20] ^= 0x40;  // a payload bit flipped
  auto bytes = bad;
  const auto good = frameOf(writer, test::sampleSetpoint());
  bytes.insert(bytes.end(), good.begin(), good.end());
  const auto frames = parseAll(parser, bytes);
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_EQ(frames[0].seq, 1);
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kBadCrc), 1);
}

TEST(MavlinkParser, AnUnknownIdIsCountedAndTheFrameAfterItParses) {
  FrameWriter writer(Address{1, 1});
  Parser parser;
  uint8_t payload[28] = {1, 2, 3};
  std::vector<uint8_t> unknown(kMaxFrameSize);
  unknown.resize(writer.writeFrame(30, 39, payload, sizeof payload, 0, unknown.data()));  // ATTITUDE
  const auto good = frameOf(writer, test::sampleSetpoint());
  unknown.insert(unknown.end(), good.begin(), good.end());
  EXPECT_EQ(parseAll(parser, unknown).size(), 1u);
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kUnknownId), 1);
  EXPECT_EQ(parser.counts().skipped_bytes, 10 + 3 - 1 + 2);  // its bytes after the marker (payload cut to 3)
}

TEST(MavlinkParser, AnOverlongPayloadAndUnknownFlagsAreRefused) {
  FrameWriter writer(Address{1, 1});
  Parser parser;
  auto long_frame = frameOf(writer, test::sampleSetpoint());
  long_frame[1] = 60;  // SET_ATTITUDE_TARGET holds at most 51
  EXPECT_TRUE(parseAll(parser, long_frame).empty());
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kBadLength), 1);
  auto flagged = frameOf(writer, test::sampleSetpoint());
  flagged[2] = 0x02;
  EXPECT_TRUE(parseAll(parser, flagged).empty());
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kBadFlags), 1);
}

TEST(MavlinkParser, AMavlink1FrameIsCountedNotDecoded) {
  Parser parser;
  // An intact MAVLink 1 HEARTBEAT (the v1 CRC covers length through payload, then the CRC extra).
  std::vector<uint8_t> v1{0xFE, 9, 0, 1, 1, 0, 0, 0, 0, 0, 2, 12, 4, 3, 3};
  uint16_t crc = crcAccumulate(v1.data() + 1, v1.size() - 1, kCrcInit);
  crc = crcAccumulate(Heartbeat::kCrcExtra, crc);
  v1.push_back(static_cast<uint8_t>(crc & 0xFF));
  v1.push_back(static_cast<uint8_t>(crc >> 8));
  FrameWriter writer(Address{1, 1});
  const auto good = frameOf(writer, test::sampleSetpoint());
  v1.insert(v1.end(), good.begin(), good.end());
  EXPECT_EQ(parseAll(parser, v1).size(), 1u);
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kVersion1), 1);
}

TEST(MavlinkParser, GarbageNeverDecodesAndFramesAmongItAreFound) {
  std::mt19937 random(20261204);
  std::uniform_int_distribution<int> byte(0, 255);
  FrameWriter writer(Address{1, 1});
  Parser parser;
  std::vector<uint8_t> stream;
  int sent = 0;
  for (int round = 0; round < 200; ++round) {
    for (int i = 0; i < 300; ++i) stream.push_back(static_cast<uint8_t>(byte(random)));
    stream.push_back(0xFD);  // a false start right before the good frame: resynchronised
    const auto good = frameOf(writer, test::sampleOdometry());
    stream.insert(stream.end(), good.begin(), good.end());
    ++sent;
  }
  // Fed as a serial stream in chunks of odd sizes.
  std::vector<Frame> frames;
  for (size_t at = 0; at < stream.size(); at += 7) {
    const size_t n = std::min<size_t>(7, stream.size() - at);
    parser.feed(stream.data() + at, n, 0, [&](const Frame& f) { frames.push_back(f); });
  }
  int good = 0;
  for (const Frame& f : frames) good += f.id == Odometry::kId && f.length == 232 ? 1 : 0;
  EXPECT_EQ(good, sent);
  EXPECT_EQ(static_cast<int>(frames.size()), sent);  // no garbage decoded as a frame
  EXPECT_GT(parser.counts().skipped_bytes, 200 * 250);
}

TEST(MavlinkParser, ByteAtATimeEqualsWholeDatagrams) {
  FrameWriter writer(Address{3, 7});
  std::vector<uint8_t> stream;
  for (int i = 0; i < 5; ++i) {
    const auto f = frameOf(writer, test::sampleOdometry());
    stream.insert(stream.end(), f.begin(), f.end());
  }
  Parser whole, bytewise;
  const auto a = parseAll(whole, stream);
  std::vector<Frame> b;
  for (uint8_t byte : stream) bytewise.feed(&byte, 1, 0, [&](const Frame& f) { b.push_back(f); });
  ASSERT_EQ(a.size(), 5u);
  ASSERT_EQ(b.size(), 5u);
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].payload, b[i].payload);
    EXPECT_EQ(a[i].source.system, 3);
    EXPECT_EQ(b[i].seq, i);
  }
}

}  // namespace
}  // namespace sdlqr::mavlink
