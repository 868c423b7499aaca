#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "sdlqr/logger/log_export.hpp"
#include "sdlqr/logger/logger_cli.hpp"
#include "sdlqr/logger/mcap_export.hpp"

namespace sdlqr::logger {

namespace {

void warnAboutDamage(const LogFileStatus& log) {
  if (log.truncated_tail_bytes > 0) {
    std::cerr << kLoggerProgram << " export: warning: '" << log.path << "' ends in a truncated event: "
              << log.truncated_tail_bytes << " bytes after byte " << log.readable_bytes
              << " unreadable (recorder killed?); exported the " << log.events << " readable events" << std::endl;
  }
  if (log.skipped_bytes > 0) {
    std::cerr << kLoggerProgram << " export: warning: '" << log.path << "' is damaged: skipped " << log.skipped_bytes
              << " bytes between events" << std::endl;
  }
}

void reportCsv(const ExportResult& result) {
  for (const ExportedChannel& c : result.channels) {
    std::cout << "  " << c.channel << "  " << (c.lcm_type.empty() ? "(unknown type)" : c.lcm_type) << "  ";
    if (c.csv_path.empty()) std::cout << c.events << " events, not exported";
    else std::cout << c.rows << " rows -> " << c.csv_path;
    if (c.decode_failures > 0) std::cout << "  (" << c.decode_failures << " failed to decode)";
    std::cout << "\n";
  }
  std::cout << "  metrics -> " << result.metrics_path << std::endl;
}

void reportMcap(const McapExportResult& result, const std::string& path) {
  int64_t undecodable = 0;
  for (const McapChannel& c : result.channels) {
    std::cout << "  mcap " << c.topic << "  " << (c.schema_name.empty() ? "x-lcm (recorded bytes)" : c.schema_name) << "  "
              << c.written << " messages";
    if (c.undecodable > 0) std::cout << "  (" << c.undecodable << " of " << c.events << " events not one whole message: not written)";
    std::cout << "\n";
    undecodable += c.undecodable;
  }
  std::cout << "  mcap -> " << path << ": " << result.messages << " messages in " << result.chunks << " chunks, "
            << result.channels.size() << " channels" << std::endl;
  if (undecodable > 0) {
    std::cerr << kLoggerProgram << " export: warning: " << undecodable
              << " events of known channels are not one whole message of their type: not in the MCAP file" << std::endl;
  }
}

}  // namespace

int runExportCommand(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string out, mcap;
  double period_s = 0.01;
  sdlqr::ArgParser parser(std::string(kLoggerProgram) + " export",
                          "Writes one CSV per channel (header: field names and units from lcmtypes/*.lcm; numbers\n"
                          "round-trip exactly) and metrics.json (rates, gaps, losses, pacing, GAINS solve times,\n"
                          "RATE_CMD jitter, last HEARTBEAT per process) from an LCM event log (--out), and/or the\n"
                          "whole log as one MCAP file for Foxglove (--mcap): every channel, JSON with the JSON Schema\n"
                          "generated from its .lcm file, and each vehicle's pose in Foxglove's own schemas.");
  parser.allowPositional(&positional, "LOG");
  parser.addOption("--out", &out, "DIR", "CSV and metrics output folder (created if missing)");
  parser.addOption("--mcap", &mcap, "FILE", "MCAP file to write (chunked, indexed, CRCs; docs/view.md)");
  parser.addOption("--rate-cmd-period", &period_s, "S", "nominal RATE_CMD period for the jitter figures (default 0.01)",
                   sdlqr::Range::above(0));
  parser.setEpilog(
      "A log whose last event is cut short (recorder killed) is exported up to that event, with a warning\n"
      "naming the bytes dropped.\n\n"
      "exit codes: 0 exported, 1 output could not be written, 2 bad arguments or a missing/unreadable log");
  parser.parseOrExit(argc, argv);
  if (positional.size() != 1) throw std::invalid_argument("export needs exactly one LOG (see export --help)");
  if (out.empty() && mcap.empty()) throw std::invalid_argument("export needs --out DIR and/or --mcap FILE");

  const auto progress = [](int percent, int64_t events) {
    std::cerr << kLoggerProgram << " export: " << percent << "% (" << events << " events)" << std::endl;
  };
  if (!out.empty()) {
    ExportOptions options;
    options.log_path = positional[0];
    options.out_dir = out;
    options.metrics.rate_command_period_s = period_s;
    options.progress = progress;
    const ExportResult result = exportLog(options);
    warnAboutDamage(result.log);
    reportCsv(result);
  }
  if (!mcap.empty()) {
    McapExportOptions options;
    options.log_path = positional[0];
    options.mcap_path = mcap;
    options.progress = progress;
    const McapExportResult result = exportMcap(options);
    if (out.empty()) warnAboutDamage(result.log);
    reportMcap(result, mcap);
  }
  return 0;
}

}  // namespace sdlqr::logger
