#pragma once
// How much of an LCM event log could be read.

#include <cstdint>
#include <string>

namespace sdlqr::logger {

struct LogFileStatus {
  std::string path;
  int64_t file_bytes = 0;
  int64_t events = 0;                // events read
  int64_t readable_bytes = 0;        // end offset of the last event read
  int64_t skipped_bytes = 0;         // bytes between events that formed no event (corruption)
  int64_t truncated_tail_bytes = 0;  // bytes after the last event that form no whole event
  int64_t first_receive_utime = 0;   // [us] log timestamp (recorder wall clock) of the first event
  int64_t last_receive_utime = 0;

  bool complete() const { return skipped_bytes == 0 && truncated_tail_bytes == 0; }
};

}  // namespace sdlqr::logger
