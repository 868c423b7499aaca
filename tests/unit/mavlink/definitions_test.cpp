// The generator's reading of the official definitions: every message's CRC extra and payload
// lengths equal the reference C library's (mavlink/c_library_v2 MAVLINK_MESSAGE_CRCS, as listed in
// PX4's docs and checked against node-mavlink's MAGIC_NUMBERS), the wire order sorts by type size,
// and a definition the generator cannot describe is refused with its line.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "sdlqr/mavlink/crc.hpp"
#include "sdlqr/mavlink/messages.hpp"
#include "sdlqr/mavlinkgen/definitions.hpp"

namespace sdlqr::mavlinkgen {
namespace {

Definitions vendored() {
  Definitions all;
  for (const char* name : {"minimal.xml", "common.xml"}) {
    std::ifstream in(std::string(SDLQR_SOURCE_DIR) + "/mavlink/definitions/" + name);
    std::ostringstream text;
    text << in.rdbuf();
    merge(all, parseDefinitions(text.str(), name));
  }
  return all;
}

const Message& byName(const Definitions& d, const std::string& name) {
  for (const Message& m : d.messages) {
    if (m.name == name) return m;
  }
  throw std::runtime_error("no message " + name);
}

TEST(MavlinkCrc, X25OfTheStandardCheckStringIs0x6F91) {
  const char* check = "123456789";  // CRC-16/MCRF4XX check value
  EXPECT_EQ(mavlink::crcAccumulate(reinterpret_cast<const uint8_t*>(check), 9, mavlink::kCrcInit), 0x6F91);
}

TEST(MavlinkDefinitions, CrcExtrasAndLengthsAreTheReferenceLibrarys) {
  const Definitions d = vendored();
  struct Expected {
    const char* name;
    uint32_t id;
    int crc_extra, min_length, max_length;
  };
  for (const Expected& e : {Expected{"HEARTBEAT", 0, 50, 9, 9}, Expected{"ATTITUDE_QUATERNION", 31, 246, 32, 48},
                            Expected{"LOCAL_POSITION_NED", 32, 185, 28, 28}, Expected{"COMMAND_LONG", 76, 152, 33, 33},
                            Expected{"COMMAND_ACK", 77, 143, 3, 10}, Expected{"SET_ATTITUDE_TARGET", 82, 49, 39, 51},
                            Expected{"HIGHRES_IMU", 105, 93, 62, 63}, Expected{"EXTENDED_SYS_STATE", 245, 130, 2, 2},
                            Expected{"ODOMETRY", 331, 91, 230, 233}}) {
    const Message& m = byName(d, e.name);
    EXPECT_EQ(m.id, e.id) << e.name;
    EXPECT_EQ(crcExtra(m), e.crc_extra) << e.name;
    EXPECT_EQ(minLength(m), e.min_length) << e.name;
    EXPECT_EQ(maxLength(m), e.max_length) << e.name;
  }
  EXPECT_EQ(d.messages.size(), 9u);
  EXPECT_EQ(d.version, 3);
}

TEST(MavlinkDefinitions, TheGeneratedHeaderCarriesTheSameConstants) {
  EXPECT_EQ(mavlink::SetAttitudeTarget::kCrcExtra, 49);
  EXPECT_EQ(mavlink::SetAttitudeTarget::kMinLength, 39);
  EXPECT_EQ(mavlink::Odometry::kMaxLength, 233);
  EXPECT_EQ(mavlink::Heartbeat().mavlink_version, 3);
  EXPECT_EQ(mavlink::mav_cmd::kDoSetMode, 176u);
  EXPECT_EQ(mavlink::mav_result::kTemporarilyRejected, 1u);
  EXPECT_EQ(mavlink::mav_landed_state::kOnGround, 1u);
  ASSERT_NE(mavlink::findMessage(331), nullptr);
  EXPECT_EQ(mavlink::findMessage(331)->crc_extra, 91);
  EXPECT_EQ(mavlink::findMessage(30), nullptr);  // ATTITUDE: PX4 streams it, this stack does not decode it
}

TEST(MavlinkDefinitions, WireOrderSortsByTypeSizeAndKeepsExtensionsLast) {
  const Definitions d = vendored();
  std::vector<std::string> names;
  for (const Field& f : wireOrder(byName(d, "SET_ATTITUDE_TARGET"))) names.push_back(f.name);
  const std::vector<std::string> expected{"time_boot_ms", "q", "body_roll_rate", "body_pitch_rate", "body_yaw_rate",
                                          "thrust", "target_system", "target_component", "type_mask", "thrust_body"};
  EXPECT_EQ(names, expected);
  names.clear();
  for (const Field& f : wireOrder(byName(d, "HEARTBEAT"))) names.push_back(f.name);
  EXPECT_EQ(names.front(), "custom_mode");
  EXPECT_EQ(names.back(), "mavlink_version");
}

TEST(MavlinkDefinitions, AnUnknownFieldTypeIsRefusedWithItsLine) {
  const std::string xml =
      "<mavlink>\n<messages>\n<message id=\"7\" name=\"X\">\n<field type=\"float16\" name=\"a\">A</field>\n"
      "</message>\n</messages>\n</mavlink>\n";
  try {
    parseDefinitions(xml, "bad.xml");
    FAIL() << "accepted an unknown type";
  } catch (const DefinitionError& e) {
    EXPECT_EQ(std::string(e.what()), "bad.xml:4: field a: unknown field type 'float16'");
  }
  EXPECT_THROW(parseDefinitions("<mavlink><messages>", "cut.xml"), DefinitionError);
}

TEST(MavlinkDefinitions, AMessageDefinedTwiceIsRefused) {
  Definitions d = vendored();
  EXPECT_THROW(merge(d, vendored()), DefinitionError);
}

}  // namespace
}  // namespace sdlqr::mavlinkgen
