#include "sdlqr/foxglove/mcap_writer.hpp"

#include <algorithm>
#include <stdexcept>

namespace sdlqr::foxglove {

namespace {

// Opcodes of the records written (the specification's "Records" section).
enum Opcode : uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

constexpr std::string_view kMagic{"\x89MCAP0\r\n", 8};

// Little-endian fields of one record's content.
class Fields {
 public:
  Fields& u8(uint8_t v) { return le(v, 1); }
  Fields& u16(uint16_t v) { return le(v, 2); }
  Fields& u32(uint32_t v) { return le(v, 4); }
  Fields& u64(uint64_t v) { return le(v, 8); }
  Fields& str(std::string_view s) {  // String: uint32 length, bytes
    u32(static_cast<uint32_t>(s.size()));
    bytes_.append(s);
    return *this;
  }
  Fields& raw(std::string_view s) {
    bytes_.append(s);
    return *this;
  }
  // Map<string, string> and Array<...>: a uint32 byte length, then the elements.
  Fields& stringMap(const std::vector<std::pair<std::string, std::string>>& entries) {
    Fields inner;
    for (const auto& [k, v] : entries) inner.str(k).str(v);
    return u32(static_cast<uint32_t>(inner.bytes_.size())).raw(inner.bytes_);
  }
  Fields& u16u64Map(const std::map<uint16_t, uint64_t>& entries) {
    Fields inner;
    for (const auto& [k, v] : entries) inner.u16(k).u64(v);
    return u32(static_cast<uint32_t>(inner.bytes_.size())).raw(inner.bytes_);
  }
  const std::string& bytes() const { return bytes_; }

 private:
  Fields& le(uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
    return *this;
  }
  std::string bytes_;
};

// <opcode><uint64 content length><content>
std::string record(uint8_t opcode, const Fields& content) {
  Fields r;
  r.u8(opcode).u64(content.bytes().size()).raw(content.bytes());
  return r.bytes();
}

}  // namespace

McapWriter::McapWriter(std::ostream& out, McapWriterOptions options) : out_(out), options_(std::move(options)) {
  emit(kMagic);
  emit(record(kHeader, Fields().str(options_.profile).str(options_.library)));
}

McapWriter::~McapWriter() {
  if (!finished_) finish();
}

uint16_t McapWriter::addSchema(std::string name, std::string encoding, std::string data) {
  if (schemas_.size() >= UINT16_MAX) throw std::invalid_argument("MCAP: more than 65535 schemas");
  const auto id = static_cast<uint16_t>(schemas_.size() + 1);
  schemas_.push_back({id, std::move(name), std::move(encoding), std::move(data)});
  schema_written_.push_back(false);
  return id;
}

uint16_t McapWriter::addChannel(uint16_t schema_id, std::string topic, std::string message_encoding,
                                std::vector<std::pair<std::string, std::string>> metadata) {
  if (schema_id > schemas_.size()) {
    throw std::invalid_argument("MCAP: channel '" + topic + "' names unknown schema id " + std::to_string(schema_id));
  }
  if (channels_.size() >= UINT16_MAX) throw std::invalid_argument("MCAP: more than 65535 channels");
  const auto id = static_cast<uint16_t>(channels_.size() + 1);
  channels_.push_back({id, schema_id, std::move(topic), std::move(message_encoding), std::move(metadata)});
  if (schema_id > 0 && !schema_written_[schema_id - 1]) {
    const Schema& schema = schemas_[schema_id - 1];
    chunk_.records += record(kSchema, Fields().u16(schema.id).str(schema.name).str(schema.encoding).str(schema.data));
    schema_written_[schema_id - 1] = true;
  }
  const Channel& c = channels_.back();
  chunk_.records +=
      record(kChannel, Fields().u16(c.id).u16(c.schema_id).str(c.topic).str(c.message_encoding).stringMap(c.metadata));
  return id;
}

void McapWriter::writeMessage(uint16_t channel_id, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
                              std::string_view data) {
  if (channel_id == 0 || channel_id > channels_.size()) {
    throw std::invalid_argument("MCAP: message on unknown channel id " + std::to_string(channel_id));
  }
  chunk_.index[channel_id].emplace_back(log_time, chunk_.records.size());
  chunk_.records += record(kMessage, Fields().u16(channel_id).u32(sequence).u64(log_time).u64(publish_time).raw(data));
  chunk_.start_time = std::min(chunk_.start_time, log_time);
  chunk_.end_time = std::max(chunk_.end_time, log_time);
  stats_.message_start_time = stats_.messages == 0 ? log_time : std::min(stats_.message_start_time, log_time);
  stats_.message_end_time = std::max(stats_.message_end_time, log_time);
  ++stats_.messages;
  ++stats_.channel_messages[channel_id];
  if (chunk_.records.size() >= options_.chunk_size) closeChunk();
}

void McapWriter::emit(std::string_view bytes) {
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  position_ += bytes.size();
  if (in_data_section_) data_crc_.update(bytes);
}

// The chunk record, then one Message Index record per channel of the chunk (offsets into the
// uncompressed records); the Chunk Index of the summary points at both.
void McapWriter::closeChunk() {
  if (chunk_.records.empty()) return;
  ChunkIndex index;
  index.start_time = chunk_.index.empty() ? 0 : chunk_.start_time;
  index.end_time = chunk_.end_time;
  index.offset = position_;
  index.records_size = chunk_.records.size();
  Fields content;
  content.u64(index.start_time).u64(index.end_time).u64(index.records_size).u32(crc32(chunk_.records)).str("");
  content.u64(index.records_size).raw(chunk_.records);
  const std::string chunk = record(kChunk, content);
  index.length = chunk.size();
  emit(chunk);
  const uint64_t indexes_start = position_;
  for (const auto& [channel, entries] : chunk_.index) {
    Fields pairs;
    for (const auto& [time, offset] : entries) pairs.u64(time).u64(offset);
    index.message_index_offsets[channel] = position_;
    emit(record(kMessageIndex, Fields().u16(channel).u32(static_cast<uint32_t>(pairs.bytes().size())).raw(pairs.bytes())));
  }
  index.index_length = position_ - indexes_start;
  chunk_indexes_.push_back(index);
  ++stats_.chunks;
  chunk_ = OpenChunk{};
}

void McapWriter::finish() {
  if (finished_) return;
  finished_ = true;
  closeChunk();
  const uint32_t data_crc = data_crc_.value();
  emit(record(kDataEnd, Fields().u32(data_crc)));
  in_data_section_ = false;
  writeSummary();
  out_.flush();
}

// Writes one group of summary records; remembers (opcode, start, length) for its Summary Offset.
void McapWriter::emitGroup(uint8_t opcode, const std::vector<std::string>& records,
                               std::vector<std::pair<uint8_t, std::pair<uint64_t, uint64_t>>>* groups) {
  const uint64_t start = position_;
  for (const std::string& r : records) emit(r);
  if (position_ > start) groups->push_back({opcode, {start, position_ - start}});
}

void McapWriter::writeSummary() {
  Crc32 summary_crc;
  const uint64_t summary_start = position_;
  std::vector<std::pair<uint8_t, std::pair<uint64_t, uint64_t>>> groups;
  std::vector<std::string> records;
  for (const Schema& s : schemas_) records.push_back(record(kSchema, Fields().u16(s.id).str(s.name).str(s.encoding).str(s.data)));
  const auto flush = [&](uint8_t opcode) {
    for (const std::string& r : records) summary_crc.update(r);
    emitGroup(opcode, records, &groups);
    records.clear();
  };
  flush(kSchema);
  for (const Channel& c : channels_) {
    records.push_back(
        record(kChannel, Fields().u16(c.id).u16(c.schema_id).str(c.topic).str(c.message_encoding).stringMap(c.metadata)));
  }
  flush(kChannel);
  Fields stats;
  stats.u64(stats_.messages).u16(static_cast<uint16_t>(schemas_.size())).u32(static_cast<uint32_t>(channels_.size()));
  stats.u32(0).u32(0).u32(stats_.chunks);  // attachments, metadata, chunks
  stats.u64(stats_.message_start_time).u64(stats_.message_end_time).u16u64Map(stats_.channel_messages);
  records.push_back(record(kStatistics, stats));
  flush(kStatistics);
  for (const ChunkIndex& c : chunk_indexes_) {
    Fields f;
    f.u64(c.start_time).u64(c.end_time).u64(c.offset).u64(c.length).u16u64Map(c.message_index_offsets);
    f.u64(c.index_length).str("").u64(c.records_size).u64(c.records_size);
    records.push_back(record(kChunkIndex, f));
  }
  flush(kChunkIndex);
  const uint64_t summary_offset_start = position_;
  for (const auto& [opcode, span] : groups) {
    const std::string r = record(kSummaryOffset, Fields().u8(opcode).u64(span.first).u64(span.second));
    summary_crc.update(r);
    emit(r);
  }
  Fields footer_head;  // the footer up to (not including) its CRC field
  footer_head.u8(kFooter).u64(8 + 8 + 4).u64(summary_start).u64(summary_offset_start);
  summary_crc.update(footer_head.bytes());
  emit(footer_head.bytes());
  emit(Fields().u32(summary_crc.value()).bytes());
  emit(kMagic);
}

}  // namespace sdlqr::foxglove
