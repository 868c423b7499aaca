#pragma once
// Writes an MCAP file (https://mcap.dev/spec, major version 0): chunked, indexed, with CRCs.
//
//   <magic><Header>
//   <Chunk [Schema][Channel] Message...><Message Index per channel>...   (chunks of ~chunk_size)
//   <Data End: CRC-32 of every byte before it>
//   <Schema...><Channel...><Statistics><Chunk Index...>                 (the summary)
//   <Summary Offset per group><Footer: summary CRC><magic>
//
// A schema and a channel are written into the chunk that is open when the channel is added, so
// every message follows the records it refers to; the summary repeats them all. Chunks are not
// compressed (compression ""). Debian has no MCAP library, so this follows the specification;
// @mcap/core, an independent reader, checks what it writes (tests/integration/view).

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "sdlqr/foxglove/crc32.hpp"

namespace sdlqr::foxglove {

struct McapWriterOptions {
  std::string profile;               // "" : no well-known profile
  std::string library = "sdlqr";     // written in the Header
  std::size_t chunk_size = 1 << 20;  // [bytes] of records after which a chunk is closed
};

struct McapStatistics {
  uint64_t messages = 0;
  uint32_t chunks = 0;
  uint64_t message_start_time = 0;  // [ns] earliest log time (0 with no message)
  uint64_t message_end_time = 0;    // [ns] latest log time
  std::map<uint16_t, uint64_t> channel_messages;
};

class McapWriter {
 public:
  // Writes the magic and the Header at once.
  explicit McapWriter(std::ostream& out, McapWriterOptions options = {});
  ~McapWriter();
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  // Ids count from 1; schema id 0 is a channel without a schema. Throws std::invalid_argument
  // past 65,535 schemas or channels, or when a channel names a schema id never returned.
  uint16_t addSchema(std::string name, std::string encoding, std::string data);
  uint16_t addChannel(uint16_t schema_id, std::string topic, std::string message_encoding,
                      std::vector<std::pair<std::string, std::string>> metadata = {});

  // Times in nanoseconds; throws std::invalid_argument for a channel id never returned.
  void writeMessage(uint16_t channel_id, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
                    std::string_view data);

  // Closes the open chunk and writes the data end, the summary, the footer and the magic. Called
  // once; the destructor calls it when the caller did not.
  void finish();

  const McapStatistics& statistics() const { return stats_; }
  // False once a write to the stream failed.
  bool good() const { return out_.good(); }

 private:
  struct Schema {
    uint16_t id = 0;
    std::string name, encoding, data;
  };
  struct Channel {
    uint16_t id = 0, schema_id = 0;
    std::string topic, message_encoding;
    std::vector<std::pair<std::string, std::string>> metadata;
  };
  struct ChunkIndex {
    uint64_t start_time = 0, end_time = 0, offset = 0, length = 0, index_length = 0, records_size = 0;
    std::map<uint16_t, uint64_t> message_index_offsets;
  };
  struct OpenChunk {
    std::string records;
    uint64_t start_time = UINT64_MAX, end_time = 0;
    std::map<uint16_t, std::vector<std::pair<uint64_t, uint64_t>>> index;  // channel -> (log time, offset)
  };

  void emit(std::string_view bytes);
  void closeChunk();
  void writeSummary();
  void emitGroup(uint8_t opcode, const std::vector<std::string>& records,
                     std::vector<std::pair<uint8_t, std::pair<uint64_t, uint64_t>>>* groups);

  std::ostream& out_;
  McapWriterOptions options_;
  uint64_t position_ = 0;
  bool in_data_section_ = true;
  bool finished_ = false;
  Crc32 data_crc_;
  std::vector<Schema> schemas_;
  std::vector<bool> schema_written_;
  std::vector<Channel> channels_;
  std::vector<ChunkIndex> chunk_indexes_;
  OpenChunk chunk_;
  McapStatistics stats_;
};

}  // namespace sdlqr::foxglove
