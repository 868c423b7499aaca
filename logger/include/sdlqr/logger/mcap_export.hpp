#pragma once
// `sdlqr-logger export LOG --mcap FILE`: the whole LCM event log as one MCAP file, for Foxglove
// and any MCAP reader (tools/examine/foxglove/mcap_writer.hpp: chunked, indexed, CRCs).
//
// Every channel of the log is an MCAP channel of the same name, every event one message with
// log_time = publish_time = the event's receive time (the recorder's clock) in ns and sequence =
// the event's number in the log (its low 32 bits). A channel of a known type (channel_types.hpp) carries the message's JSON (schema: the JSON
// Schema generated from its .lcm file); any other channel the recorded bytes, with encoding
// "x-lcm" and no schema. Beside them each vehicle's pose in Foxglove's own schemas
// (vehicle_scene.hpp): a FrameTransform per SIM_TRUTH, a FrameTransform and a PoseInFrame per
// STATE_EST, and a SceneUpdate every 0.5 s of log time. A known channel's event whose bytes are
// not one whole message of its type cannot be written as JSON: it is counted, not written.
// A log with a torn tail (recorder killed) is exported up to its last whole event.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sdlqr/logger/log_file_status.hpp"

namespace sdlqr::logger {

struct McapExportOptions {
  std::string log_path;
  std::string mcap_path;
  std::size_t chunk_size = 1 << 20;  // [bytes] of records per MCAP chunk
  std::function<void(int percent, int64_t events)> progress;  // each further 10 % of the log read
};

struct McapChannel {
  std::string topic;
  std::string schema_name;     // "sdlqr.imu_t", "foxglove.FrameTransform"; "" for x-lcm
  int64_t events = 0;          // of the log (0 for a channel derived for Foxglove)
  int64_t written = 0;         // messages in the MCAP file
  int64_t undecodable = 0;     // events not written: not one whole message of the channel's type
};

struct McapExportResult {
  LogFileStatus log;
  std::vector<McapChannel> channels;  // in order of first appearance
  uint64_t messages = 0;
  uint32_t chunks = 0;
};

// Throws LogError when the log is missing, unreadable or holds no event (nothing is written
// then); std::runtime_error when the file cannot be written.
McapExportResult exportMcap(const McapExportOptions& options);

}  // namespace sdlqr::logger
