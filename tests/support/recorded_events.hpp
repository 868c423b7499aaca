#pragma once
// A recorded log's events in memory, and a list of events written back to a log through the
// logger's own Recorder: for the test helpers that read or rewrite a flight (export_roundtrip_check,
// log_without). A header, so each helper's binary compiles it as its own.

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "sdlqr/logger/log_reader.hpp"
#include "sdlqr/logger/recorder.hpp"

namespace sdlqr::test {

struct RecordedEvent {
  std::string channel;
  std::vector<uint8_t> bytes;
  int64_t receive_utime = 0;
};

inline std::vector<RecordedEvent> readEvents(const std::string& path) {
  logger::LogReader reader(path);
  std::vector<RecordedEvent> events;
  logger::LogEvent event;
  while (reader.next(&event)) {
    events.push_back({std::string(event.channel), std::vector<uint8_t>(event.data, event.data + event.size),
                      event.receive_utime});
  }
  return events;
}

// Throws std::runtime_error when an event cannot be queued or written.
inline void writeEvents(const std::string& path, const std::vector<RecordedEvent>& events) {
  logger::RecorderOptions options;
  options.path = path;
  options.queue_events = events.size() + 1;  // the whole log queued at once: nothing dropped
  options.queue_bytes = std::numeric_limits<std::size_t>::max();
  logger::Recorder recorder(options);
  for (const RecordedEvent& e : events) {
    if (!recorder.push(e.channel, e.bytes.data(), e.bytes.size(), e.receive_utime)) throw std::runtime_error("queue full");
  }
  recorder.stop();
  if (recorder.stats().write_errors > 0) throw std::runtime_error("cannot write " + path);
}

}  // namespace sdlqr::test
