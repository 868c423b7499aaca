// Frames as the sender writes them: header layout, MAVLink 2's zero truncation (never below one
// byte), the sequence number, the CRC over header and payload plus the CRC extra, and the lengths
// PX4's docs measured with node-mavlink (SET_ATTITUDE_TARGET 51 bytes, ODOMETRY 244).

#include <gtest/gtest.h>

#include "mavlink_test_support.hpp"
#include "sdlqr/mavlink/crc.hpp"

namespace sdlqr::mavlink {
namespace {

using test::frameOf;

TEST(MavlinkFrame, HeaderHoldsLengthSequenceAddressAndId) {
  FrameWriter writer(Address{1, 191});
  const auto bytes = frameOf(writer, test::sampleOdometry());
  ASSERT_EQ(bytes.size(), 244u);  // 232 payload bytes: the trailing quality = 0 is cut
  EXPECT_EQ(bytes[0], 0xFD);
  EXPECT_EQ(bytes[1], 232);
  EXPECT_EQ(bytes[2], 0);  // unsigned
  EXPECT_EQ(bytes[3], 0);
  EXPECT_EQ(bytes[4], 0);  // first frame
  EXPECT_EQ(bytes[5], 1);
  EXPECT_EQ(bytes[6], 191);
  EXPECT_EQ(bytes[7] | (bytes[8] << 8) | (bytes[9] << 16), 331);
  EXPECT_EQ(frameOf(writer, test::sampleOdometry())[4], 1);  // the sequence counts up
}

TEST(MavlinkFrame, ChecksumIsX25OverHeaderAndPayloadThenTheCrcExtra) {
  FrameWriter writer(Address{1, 1});
  const auto bytes = frameOf(writer, test::sampleSetpoint());
  ASSERT_EQ(bytes.size(), 51u);  // payload cut from 51 to 39 bytes (thrust_body is zero)
  uint16_t crc = crcAccumulate(bytes.data() + 1, 9 + 39, kCrcInit);
  crc = crcAccumulate(SetAttitudeTarget::kCrcExtra, crc);
  EXPECT_EQ(bytes[49], crc & 0xFF);
  EXPECT_EQ(bytes[50], crc >> 8);
}

TEST(MavlinkFrame, AllZeroPayloadKeepsOneByte) {
  uint8_t zeros[9] = {};
  EXPECT_EQ(truncatedLength(zeros, 9), 1u);
  uint8_t last[3] = {0, 0, 7};
  EXPECT_EQ(truncatedLength(last, 3), 3u);
  FrameWriter writer(Address{1, 1});
  ExtendedSysState empty;
  EXPECT_EQ(frameOf(writer, empty).size(), 10u + 1u + 2u);
}

TEST(MavlinkFrame, PayloadIsLittleEndianInWireOrder) {
  FrameWriter writer(Address{1, 1});
  SetAttitudeTarget m = test::sampleSetpoint();
  m.time_boot_ms = 0x04030201;
  const auto bytes = frameOf(writer, m);
  EXPECT_EQ(bytes[10], 0x01);
  EXPECT_EQ(bytes[13], 0x04);
  float w = 0.0f;
  wire::get(bytes.data() + 14, w);  // q[0] follows time_boot_ms
  EXPECT_EQ(w, 1.0f);
  EXPECT_EQ(bytes[10 + 36], 1);    // target_system after the nine 4-byte fields
  EXPECT_EQ(bytes[10 + 38], 128);  // type_mask: attitude ignored
}

}  // namespace
}  // namespace sdlqr::mavlink
