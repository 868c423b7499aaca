// McapWriter: the file's structure, offsets, indexes and CRCs as the MCAP specification defines
// them, walked record by record.

#include <gtest/gtest.h>

#include <sstream>

#include "mcap_reading.hpp"
#include "sdlqr/foxglove/crc32.hpp"
#include "sdlqr/foxglove/mcap_writer.hpp"

namespace sdlqr::foxglove {
namespace {

using testing::Cursor;
using testing::Record;

constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

// Three channels, 300 messages, chunks of ~1 KiB: several chunks, a channel with no message.
std::string writeSample(McapStatistics* stats = nullptr) {
  std::ostringstream out;
  McapWriter w(out, {"", "test", 1024});
  const uint16_t schema = w.addSchema("sdlqr.imu_t", "jsonschema", "{\"type\": \"object\"}");
  const uint16_t a = w.addChannel(schema, "IMU", "json", {{"lcm_type", "imu_t"}});
  const uint16_t b = w.addChannel(schema, "QUAD1/IMU", "json");
  w.addChannel(0, "FOREIGN", "x-lcm");
  for (uint32_t i = 0; i < 300; ++i) {
    const std::string data = "{\"seq\": " + std::to_string(i) + "}";
    w.writeMessage(i % 3 == 0 ? b : a, i, 1000 + 10ull * i, 1000 + 10ull * i, data);
  }
  w.finish();
  if (stats) *stats = w.statistics();
  return out.str();
}

TEST(Crc32, MatchesTheCheckValueOfTheStandard) {
  EXPECT_EQ(crc32("123456789"), 0xCBF43926u);  // CRC-32/ISO-HDLC check value
  Crc32 pieces;
  pieces.update("1234");
  pieces.update("56789");
  EXPECT_EQ(pieces.value(), 0xCBF43926u);
  EXPECT_EQ(crc32(""), 0u);
}

TEST(McapWriter, FramesTheFileWithMagicHeaderFooterAndSummaryCrc) {
  const std::string file = writeSample();
  ASSERT_GT(file.size(), 2 * kMagic.size());
  EXPECT_EQ(file.substr(0, 8), kMagic);
  EXPECT_EQ(file.substr(file.size() - 8), kMagic);
  // Footer: opcode, length 20, summary_start, summary_offset_start, summary_crc.
  Cursor footer{std::string_view(file).substr(file.size() - 8 - 29, 29)};
  EXPECT_EQ(footer.u8(), 0x02);
  EXPECT_EQ(footer.u64(), 20u);
  const uint64_t summary_start = footer.u64();
  const uint64_t summary_offset_start = footer.u64();
  const uint32_t summary_crc = footer.u32();
  ASSERT_GT(summary_offset_start, summary_start);
  // The CRC covers the summary, the summary offsets and the footer up to its CRC field.
  EXPECT_EQ(summary_crc, crc32(std::string_view(file).substr(summary_start, file.size() - 8 - 4 - summary_start)));
  // The record before the summary is the data end, whose CRC covers everything before it.
  Cursor data_end{std::string_view(file).substr(summary_start - 13, 13)};
  EXPECT_EQ(data_end.u8(), 0x0F);
  EXPECT_EQ(data_end.u64(), 4u);
  EXPECT_EQ(data_end.u32(), crc32(std::string_view(file).substr(0, summary_start - 13)));
}

TEST(McapWriter, ChunksHoldTheirRecordsWithCrcAndAreIndexedPerChannel) {
  McapStatistics stats;
  const std::string file = writeSample(&stats);
  const std::vector<Record> data = testing::records(std::string_view(file).substr(8, file.size() - 16), 8);
  ASSERT_EQ(data.front().opcode, 0x01);  // header
  int chunks = 0, messages = 0;
  for (std::size_t i = 0; i < data.size() && data[i].opcode != 0x0F; ++i) {
    if (data[i].opcode != 0x06) continue;
    ++chunks;
    Cursor c{data[i].content};
    const uint64_t start = c.u64(), end = c.u64(), size = c.u64();
    const uint32_t crc = c.u32();
    EXPECT_EQ(c.str(), "");  // uncompressed
    const std::string_view body = c.take(c.u64());
    EXPECT_EQ(body.size(), size);
    EXPECT_EQ(crc, crc32(body));
    std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> expected;  // channel -> (time, offset)
    for (const Record& r : testing::records(body)) {
      if (r.opcode != 0x05) continue;
      Cursor m{r.content};
      const uint16_t channel = m.u16();
      m.u32();
      const uint64_t log_time = m.u64();
      EXPECT_GE(log_time, start);
      EXPECT_LE(log_time, end);
      expected[channel].emplace_back(log_time, r.offset);
      ++messages;
    }
    // Then one message index per channel of the chunk, pointing at each message.
    for (const auto& [channel, entries] : expected) {
      ASSERT_EQ(data[++i].opcode, 0x07);
      Cursor index{data[i].content};
      EXPECT_EQ(index.u16(), channel);
      EXPECT_EQ(index.u32(), entries.size() * 16);
      for (const auto& [time, offset] : entries) {
        EXPECT_EQ(index.u64(), time);
        EXPECT_EQ(index.u64(), offset);
      }
    }
  }
  EXPECT_GT(chunks, 3);
  EXPECT_EQ(static_cast<uint32_t>(chunks), stats.chunks);
  EXPECT_EQ(messages, 300);
  EXPECT_EQ(stats.messages, 300u);
  EXPECT_EQ(stats.channel_messages.at(1), 200u);
  EXPECT_EQ(stats.channel_messages.at(2), 100u);
}

TEST(McapWriter, SummaryRepeatsSchemasAndChannelsAndIndexesEveryChunk) {
  const std::string file = writeSample();
  Cursor footer{std::string_view(file).substr(file.size() - 8 - 29 + 9, 16)};
  const uint64_t summary_start = footer.u64(), offsets_start = footer.u64();
  const std::vector<Record> summary =
      testing::records(std::string_view(file).substr(summary_start, offsets_start - summary_start), summary_start);
  std::map<uint8_t, int> counts;
  for (const Record& r : summary) ++counts[r.opcode];
  EXPECT_EQ(counts[0x03], 1);  // schema
  EXPECT_EQ(counts[0x04], 3);  // channels, the one without messages too
  EXPECT_EQ(counts[0x0B], 1);  // statistics
  EXPECT_GT(counts[0x08], 3);  // chunk indexes
  for (const Record& r : summary) {
    if (r.opcode != 0x08) continue;
    Cursor c{r.content};
    c.u64();
    c.u64();
    const uint64_t offset = c.u64(), length = c.u64();
    EXPECT_EQ(static_cast<uint8_t>(file.at(offset)), 0x06);  // it points at a chunk record
    Cursor chunk{std::string_view(file).substr(offset + 1, 8)};
    EXPECT_EQ(chunk.u64() + 9, length);
    Cursor offsets{c.take(c.u32())};
    while (!offsets.done()) {
      offsets.u16();
      EXPECT_EQ(static_cast<uint8_t>(file.at(offsets.u64())), 0x07);  // and at its message indexes
    }
  }
  // One summary offset per group, each pointing at the group's first record.
  const std::vector<Record> groups =
      testing::records(std::string_view(file).substr(offsets_start, file.size() - 8 - 29 - offsets_start), offsets_start);
  EXPECT_EQ(groups.size(), 4u);
  for (const Record& g : groups) {
    Cursor c{g.content};
    const uint8_t opcode = c.u8();
    EXPECT_EQ(static_cast<uint8_t>(file.at(c.u64())), opcode);
  }
}

TEST(McapWriter, RefusesUnknownIds) {
  std::ostringstream out;
  McapWriter w(out);
  EXPECT_THROW(w.addChannel(7, "X", "json"), std::invalid_argument);
  EXPECT_THROW(w.writeMessage(1, 0, 0, 0, "{}"), std::invalid_argument);
}

TEST(McapWriter, AnEmptyFileIsStillWhole) {
  std::ostringstream out;
  { McapWriter w(out); }  // the destructor finishes it
  const std::string file = out.str();
  EXPECT_EQ(file.substr(0, 8), kMagic);
  EXPECT_EQ(file.substr(file.size() - 8), kMagic);
}

}  // namespace
}  // namespace sdlqr::foxglove
