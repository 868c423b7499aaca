// Signing (mavlink.io message_signing): a frame signed with the key passes; the wrong key, an
// unsigned frame, a replayed or reordered frame and a new stream more than a minute old are
// refused and counted; without a key a signed frame passes unchecked. The signature is the first
// six bytes of SHA-256 over key, frame and trailer, byte for byte (node-mavlink checks the same
// in tests/px4/node_mavlink_check.mjs).

#include <gtest/gtest.h>

#include <nettle/sha2.h>

#include "mavlink_test_support.hpp"

namespace sdlqr::mavlink {
namespace {

using test::frameOf;
using test::parseAll;

SigningKey keyOf(uint8_t seed) {
  SigningKey key;
  for (size_t i = 0; i < key.bytes.size(); ++i) key.bytes[i] = static_cast<uint8_t>(seed + 3 * i);
  return key;
}

constexpr uint64_t kNow = 372000000000ULL;  // ~2026 on the signing clock

TEST(MavlinkSigning, TheTrailerIsLinkTimestampAndTruncatedSha256) {
  FrameWriter writer(Address{1, 191});
  writer.enableSigning(keyOf(1), 7);
  const auto bytes = frameOf(writer, test::sampleSetpoint(), kNow);
  ASSERT_EQ(bytes.size(), 51u + 13u);
  EXPECT_EQ(bytes[2], kIncompatSigned);
  const uint8_t* trailer = bytes.data() + 51;
  EXPECT_EQ(trailer[0], 7);
  uint64_t timestamp = 0;
  for (int i = 5; i >= 0; --i) timestamp = (timestamp << 8) | trailer[1 + i];
  EXPECT_EQ(timestamp, kNow);
  sha256_ctx ctx;
  sha256_init(&ctx);
  const SigningKey key = keyOf(1);
  sha256_update(&ctx, 32, key.bytes.data());
  sha256_update(&ctx, 51 + 7, bytes.data());
  uint8_t digest[32];
  sha256_digest(&ctx, 32, digest);
  EXPECT_TRUE(std::equal(digest, digest + 6, trailer + 7));
}

TEST(MavlinkSigning, TimestampsOfOneLinkAlwaysIncrease) {
  FrameWriter writer(Address{1, 191});
  writer.enableSigning(keyOf(1), 0);
  const auto a = frameOf(writer, test::sampleSetpoint(), kNow);
  const auto b = frameOf(writer, test::sampleSetpoint(), kNow);  // the same clock reading
  EXPECT_EQ(b[51 + 1], static_cast<uint8_t>(a[51 + 1] + 1));
}

TEST(MavlinkSigning, OnlyTheKeysFramesPass) {
  FrameWriter good(Address{1, 1}), wrong(Address{1, 1}), plain(Address{1, 1});
  good.enableSigning(keyOf(1), 0);
  wrong.enableSigning(keyOf(2), 0);
  Parser parser;
  parser.requireSigning(keyOf(1));
  EXPECT_EQ(parseAll(parser, frameOf(good, test::sampleOdometry(), kNow), kNow).size(), 1u);
  EXPECT_TRUE(parseAll(parser, frameOf(wrong, test::sampleOdometry(), kNow + 10), kNow).empty());
  EXPECT_TRUE(parseAll(parser, frameOf(plain, test::sampleOdometry()), kNow).empty());
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kBadSignature), 1);
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kUnsigned), 1);
  EXPECT_EQ(parser.counts().frames, 1);
}

TEST(MavlinkSigning, ReplayedAndStaleFramesAreRefused) {
  FrameWriter writer(Address{1, 1});
  writer.enableSigning(keyOf(1), 0);
  Parser parser;
  parser.requireSigning(keyOf(1));
  const auto first = frameOf(writer, test::sampleOdometry(), kNow);
  const auto second = frameOf(writer, test::sampleOdometry(), kNow + 100);
  EXPECT_EQ(parseAll(parser, second, kNow).size(), 1u);
  EXPECT_TRUE(parseAll(parser, first, kNow).empty());   // older than the newest of its stream
  EXPECT_TRUE(parseAll(parser, second, kNow).empty());  // the same frame again
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kReplayed), 2);
  // Another stream (link 1) whose first frame is over a minute old.
  FrameWriter old(Address{1, 1});
  old.enableSigning(keyOf(1), 1);
  EXPECT_TRUE(parseAll(parser, frameOf(old, test::sampleOdometry(), kNow - kNewStreamWindow - 1), kNow).empty());
  EXPECT_EQ(parser.counts().droppedOf(FrameDrop::kReplayed), 3);
}

TEST(MavlinkSigning, WithoutAKeyASignedFramePassesUnchecked) {
  FrameWriter writer(Address{1, 1});
  writer.enableSigning(keyOf(9), 0);
  Parser parser;
  const auto frames = parseAll(parser, frameOf(writer, test::sampleSetpoint(), kNow));
  ASSERT_EQ(frames.size(), 1u);
  EXPECT_TRUE(frames[0].is_signed);
}

TEST(MavlinkSigning, SigningClockCountsTenMicrosecondsSince2015) {
  EXPECT_EQ(signingTime(1420070400LL * 1000000), 0u);
  EXPECT_EQ(signingTime(1420070400LL * 1000000 + 10), 1u);
  EXPECT_EQ(signingTime(0), 0u);
}

}  // namespace
}  // namespace sdlqr::mavlink
