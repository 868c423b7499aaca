#pragma once
// The command lines of sdlqr-logger: `record` (the process) and `export` (a tool on a log).

#include <string>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/logger/recorder.hpp"

namespace sdlqr::logger {

inline constexpr const char* kLoggerProgram = "sdlqr-logger";

struct RecordCommand {
  ProcessOptions process;
  RecorderOptions recorder;  // path: --out, or <dir>/<date>-<scenario>.lcmlog
  std::string pattern;       // LCM regex of the channels to record
  std::string scenario;
  double duration_s = 0.0;   // [s] of wall time, 0: until a signal
};

// Parses `record` options (exits on --help or a bad option, as ArgParser); throws
// std::invalid_argument naming the option when a value is unusable.
RecordCommand parseRecordCommand(int argc, const char* const* argv);

// After recording: the summary line on stdout, the write error on stderr; returns the exit code
// (1 when anything could not be written).
int reportRecording(const RecorderStats& stats, const std::string& path);

// `export LOG --out DIR`: CSV per channel + metrics.json; `--mcap FILE`: the log as MCAP
// (mcap_export.hpp). Returns the exit code.
int runExportCommand(int argc, const char* const* argv);

}  // namespace sdlqr::logger
