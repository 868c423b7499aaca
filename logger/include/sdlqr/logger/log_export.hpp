#pragma once
// `sdlqr-logger export`: one CSV per channel plus metrics.json from an LCM event log.
//
// Every channel of a known type (channel_types.hpp), of any vehicle, becomes
// <out_dir>/<channel>.csv ("QUAD1/IMU" -> QUAD1/IMU.csv): a header row with the field names and
// units generated from lcmtypes/*.lcm, then one row per decoded message in log order (CSV
// format: csv.hpp). Channels of unknown type are counted in metrics.json only. The log is read
// once, streaming, so long logs need no memory beyond the metrics' per-message times.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sdlqr/logger/log_file_status.hpp"
#include "sdlqr/logger/metrics.hpp"

namespace sdlqr::logger {

struct ExportOptions {
  std::string log_path;
  std::string out_dir;  // created if missing; existing CSVs of the same channels are replaced
  MetricsOptions metrics;
  // Called each time another 10 % of the file has been read (percent = 10, 20, ... 100).
  std::function<void(int percent, int64_t events)> progress;
};

struct ExportedChannel {
  std::string channel;
  std::string lcm_type;  // empty for a channel of unknown type (no CSV)
  std::string csv_path;  // empty when no CSV was written
  int64_t events = 0;
  int64_t rows = 0;
  int64_t decode_failures = 0;
};

struct ExportResult {
  LogFileStatus log;
  std::vector<ExportedChannel> channels;  // by channel name
  std::string metrics_path;
  LogMetrics metrics;
};

// Throws LogError when the log is missing, unreadable or holds no event (nothing is written
// then); std::runtime_error when an output file cannot be written.
ExportResult exportLog(const ExportOptions& options);

}  // namespace sdlqr::logger
