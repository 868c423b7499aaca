#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sdlqr/logger/log_export.hpp"
#include "sdlqr/logger/logger_cli.hpp"

namespace sdlqr::logger {

int runExportCommand(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string out;
  double period_s = 0.01;
  sdlqr::ArgParser parser(std::string(kLoggerProgram) + " export",
                          "Writes one CSV per channel (header: field names and units from lcmtypes/*.lcm; numbers\n"
                          "round-trip exactly) and metrics.json (rates, gaps, losses, pacing, GAINS solve times,\n"
                          "RATE_CMD jitter, last HEARTBEAT per process) from an LCM event log.");
  parser.allowPositional(&positional, "LOG");
  parser.addOption("--out", &out, "DIR", "output folder (created if missing)");
  parser.addOption("--rate-cmd-period", &period_s, "S", "nominal RATE_CMD period for the jitter figures (default 0.01)");
  parser.setEpilog(
      "A log whose last event is cut short (recorder killed) is exported up to that event, with a warning.\n\n"
      "exit codes: 0 exported, 1 output could not be written, 2 bad arguments or a missing/unreadable log");
  parser.parseOrExit(argc, argv);
  if (positional.size() != 1) throw std::invalid_argument("export needs exactly one LOG (see export --help)");
  if (out.empty()) throw std::invalid_argument("export needs --out DIR");
  if (!(period_s > 0.0)) throw std::invalid_argument("--rate-cmd-period must be > 0");

  ExportOptions options;
  options.log_path = positional[0];
  options.out_dir = out;
  options.metrics.rate_command_period_s = period_s;
  options.progress = [](int percent, int64_t events) {
    std::cerr << kLoggerProgram << " export: " << percent << "% (" << events << " events)" << std::endl;
  };
  const ExportResult result = exportLog(options);
  const LogFileStatus& log = result.log;
  if (log.truncated_tail_bytes > 0) {
    std::cerr << kLoggerProgram << " export: warning: '" << log.path << "' ends in a truncated event: "
              << log.truncated_tail_bytes << " bytes after byte " << log.readable_bytes
              << " unreadable (recorder killed?); exported the " << log.events << " readable events" << std::endl;
  }
  if (log.skipped_bytes > 0) {
    std::cerr << kLoggerProgram << " export: warning: '" << log.path << "' is damaged: skipped " << log.skipped_bytes
              << " bytes between events" << std::endl;
  }
  for (const ExportedChannel& c : result.channels) {
    std::cout << "  " << c.channel << "  " << (c.lcm_type.empty() ? "(unknown type)" : c.lcm_type) << "  ";
    if (c.csv_path.empty()) std::cout << c.events << " events, not exported";
    else std::cout << c.rows << " rows -> " << c.csv_path;
    if (c.decode_failures > 0) std::cout << "  (" << c.decode_failures << " failed to decode)";
    std::cout << "\n";
  }
  std::cout << "  metrics -> " << result.metrics_path << std::endl;
  return 0;
}


}  // namespace sdlqr::logger
