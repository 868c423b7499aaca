#pragma once
// Iterates the events of an LCM event log (.lcmlog, as written by lcm-logger or sdlqr-logger)
// through LCM's own event-log reader. No LCM type leaks out of this header.
//
// Damage is tolerated, not hidden: bytes between two events that form no event are skipped
// (LCM's reader resynchronizes on the next sync word) and counted; a last event cut short (a
// recorder killed with kill -9) ends the iteration and is counted as truncated tail bytes.
// status() tells the caller what was readable.

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "sdlqr/logger/log_file_status.hpp"

namespace sdlqr::logger {

// A log that cannot be opened or holds no event at all. Derives from std::invalid_argument so
// runMain reports it in one line with exit code 2.
class LogError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct LogEvent {
  int64_t event_number = 0;   // as stored in the log
  int64_t receive_utime = 0;  // [us] recorder wall clock when the message arrived
  std::string_view channel;
  const uint8_t* data = nullptr;  // valid until the next call of next()
  int64_t size = 0;
};

class LogReader {
 public:
  // Throws LogError if `path` is missing, not a regular file, or unreadable.
  explicit LogReader(const std::string& path);
  ~LogReader();
  LogReader(const LogReader&) = delete;
  LogReader& operator=(const LogReader&) = delete;

  // False once no further event can be read.
  bool next(LogEvent* event);

  const LogFileStatus& status() const { return status_; }
  int64_t position() const { return status_.readable_bytes; }  // for progress reports

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  LogFileStatus status_;
};

// For a tool that needs at least one event: reads the first into *event; throws LogError naming
// the log when it holds none (an empty file, or not an LCM event log).
void readFirstEvent(LogReader& reader, LogEvent* event);

// Calls report(percent, events) each time another 10 % of the log's bytes has been read.
class ReadProgress {
 public:
  using Report = std::function<void(int percent, int64_t events)>;
  explicit ReadProgress(Report report) : report_(std::move(report)) {}
  void update(const LogReader& reader);

 private:
  Report report_;
  int next_percent_ = 10;
};

}  // namespace sdlqr::logger
