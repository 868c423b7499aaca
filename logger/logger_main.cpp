// sdlqr-logger: records the bus to an LCM event log, and exports a log to CSV + metrics.json.
// Thin: the work is in the sdlqr_logger library (Recorder, exportLog).

#include <regex.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/logger/log_export.hpp"
#include "sdlqr/logger/log_naming.hpp"
#include "sdlqr/logger/recorder.hpp"
#include "sdlqr/bus/node.hpp"

namespace {

constexpr const char* kProgram = "sdlqr-logger";
constexpr int kRawQueueCapacity = 10000;  // LCM-side queue; our handler empties it quickly

// LCM anchors a subscription pattern as ^pattern$ and compiles it as a POSIX extended regex.
void checkChannelRegex(const std::string& pattern) {
  regex_t compiled;
  const std::string anchored = "^" + pattern + "$";
  const int status = regcomp(&compiled, anchored.c_str(), REG_EXTENDED | REG_NOSUB);
  if (status != 0) {
    char text[256];
    regerror(status, &compiled, text, sizeof text);
    throw std::invalid_argument("--channels '" + pattern + "': " + text);
  }
  regfree(&compiled);
}

// All our messages start with int64_t utime after LCM's 8-byte fingerprint (big-endian).
bool peekUtime(const std::string& channel, const void* data, uint32_t size, int64_t* utime) {
  if (size < 16 || !sdlqr::logger::findChannelType(sdlqr::logger::splitChannel(channel).base)) return false;
  const auto* bytes = static_cast<const uint8_t*>(data) + 8;
  uint64_t value = 0;
  for (int i = 0; i < 8; ++i) value = (value << 8) | bytes[i];
  *utime = static_cast<int64_t>(value);
  return true;
}

void createFolder(const std::string& option, const std::filesystem::path& folder) {
  if (folder.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error) throw std::invalid_argument(option + " '" + folder.string() + "': " + error.message());
}

// --out names the file (a launcher may still pass --scenario: it is checked and reported);
// otherwise the name is <dir>/<date>-<scenario>.lcmlog.
std::string logPath(const std::string& out, const std::string& dir, const std::string& scenario) {
  const std::string name = scenario.empty() ? "flight" : scenario;
  const std::string reason = sdlqr::logger::invalidScenarioReason(name);
  if (!reason.empty()) throw std::invalid_argument("--scenario: " + reason);
  if (!out.empty()) {
    if (!dir.empty()) throw std::invalid_argument("--out excludes --dir");
    createFolder("--out", std::filesystem::path(out).parent_path());
    return out;
  }
  const std::string folder = dir.empty() ? "." : dir;
  createFolder("--dir", folder);
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  localtime_r(&now, &local);
  return sdlqr::logger::scenarioLogPath(folder, name, local);
}

struct RecorderCounters {
  sdlqr::bus::Counters::Id written, bytes, overflow, write_errors, flushes, max_depth;
};

void setCounter(sdlqr::bus::Counters& counters, sdlqr::bus::Counters::Id id, int64_t value) {
  counters.increment(id, value - counters.value(id));
}

void publishStats(sdlqr::bus::Node& node, const RecorderCounters& ids, const sdlqr::logger::RecorderStats& s) {
  sdlqr::bus::Counters& c = node.counters();
  const int64_t new_errors = s.write_errors - c.value(ids.write_errors);
  for (int64_t i = 0; i < new_errors; ++i) node.countError();
  setCounter(c, ids.written, s.written);
  setCounter(c, ids.bytes, s.bytes_written);
  setCounter(c, ids.overflow, s.dropped);
  setCounter(c, ids.write_errors, s.write_errors);
  setCounter(c, ids.flushes, s.flushes);
  setCounter(c, ids.max_depth, s.max_queue_depth);
  if (s.write_errors > 0) {
    node.setState(sdlqr::bus::ProcessState::kDegraded);
    node.setLastError(s.last_error);
  }
}

int runRecord(int argc, const char* const* argv) {
  sdlqr::ProcessOptions process;
  std::string out;
  std::string dir;
  std::string scenario;
  std::string channels;
  double duration_s = 0.0;
  sdlqr::ArgParser parser(std::string(kProgram) + " [record]",
                          "Records every LCM channel (or those matching --channels) to a standard LCM event log,\n"
                          "readable by lcm-logplayer. Flushes at least every 0.2 s; stops on SIGINT/SIGTERM or\n"
                          "after --duration, with everything written. Never overwrites a file.");
  parser.addOption("--out", &out, "FILE", "log file to create (its folder is created if missing)");
  parser.addOption("--dir", &dir, "DIR", "folder for <YYYYmmdd-HHMMSS>-<scenario>.lcmlog (default: .)");
  parser.addOption("--scenario", &scenario, "NAME", "scenario part of the file name (default: flight)");
  parser.addOption("--channels", &channels, "REGEX",
                   "channels to record, LCM regex on the full name (default: all; with --vehicle, PREFIX/.*)");
  parser.addOption("--duration", &duration_s, "S", "stop after S seconds of wall time (default: until a signal)");
  parser.addOption("--lcm-url", &process.lcm_url, "URL",
                   "LCM provider (default: $LCM_DEFAULT_URL or udpm://239.255.76.67:7667?ttl=0)");
  parser.addOption("--vehicle", &process.vehicle, "PREFIX", "vehicle to record; also prefixes this logger's HEARTBEAT");
  sdlqr::addBusLayoutOption(parser, &process);
  parser.setEpilog(
      "Other mode: sdlqr-logger export LOG --out DIR   (CSV per channel + metrics.json; see export --help)\n\n"
      "exit codes: 0 recorded, 1 write errors or fatal error, 2 bad arguments or the file exists");
  parser.parseOrExit(argc, argv);
  if (duration_s < 0.0) throw std::invalid_argument("--duration must be >= 0");
  const std::string pattern = !channels.empty() ? channels : (process.vehicle.empty() ? ".*" : process.vehicle + "/.*");
  checkChannelRegex(pattern);

  sdlqr::bus::Node node(kProgram, process);
  sdlqr::logger::RecorderOptions options;
  options.path = logPath(out, dir, scenario);
  sdlqr::logger::Recorder recorder(options);

  sdlqr::bus::Counters& counters = node.counters();
  const RecorderCounters ids{counters.add("logger.written"),      counters.add("logger.bytes"),
                             counters.add("logger.queue_overflow"), counters.add("logger.write_errors"),
                             counters.add("logger.flushes"),      counters.add("logger.queue_max_depth")};
  int64_t latest_utime = 0;
  node.subscribeRaw(
      pattern,
      [&](const std::string& channel, const void* data, uint32_t size, int64_t receive_utime) {
        if (!recorder.push(channel, data, size, receive_utime)) node.countDropped(1);
        int64_t utime = 0;
        if (peekUtime(channel, data, size, &utime) && utime > latest_utime) latest_utime = utime;
      },
      kRawQueueCapacity);
  node.setState(sdlqr::bus::ProcessState::kRunning);
  std::cout << kProgram << ": recording '" << pattern << "'" << (scenario.empty() ? "" : " (scenario " + scenario + ")")
            << " to " << recorder.path() << std::endl;

  const auto start = std::chrono::steady_clock::now();
  auto next_stats = start;
  while (node.spin(50)) {
    const auto now = std::chrono::steady_clock::now();
    if (now >= next_stats) {
      node.setSimTime(latest_utime);
      publishStats(node, ids, recorder.stats());
      next_stats = now + std::chrono::milliseconds(100);
    }
    if (duration_s > 0.0 && now - start >= std::chrono::duration<double>(duration_s)) break;
  }

  // Record our own last heartbeat (final counters, STOPPING) before closing the file.
  publishStats(node, ids, recorder.stats());
  node.shutdown();
  const auto drain_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (std::chrono::steady_clock::now() < drain_until) node.drain(20);
  recorder.stop();
  const sdlqr::logger::RecorderStats s = recorder.stats();
  std::cout << kProgram << ": wrote " << s.written << " messages (" << s.bytes_written << " bytes) to "
            << recorder.path() << "; dropped " << s.dropped << ", write errors " << s.write_errors << std::endl;
  if (s.write_errors > 0) {
    std::cerr << kProgram << ": " << s.last_error << "\n";
    return 1;
  }
  return 0;
}

int runExport(int argc, const char* const* argv) {
  std::vector<std::string> positional;
  std::string out;
  double period_s = 0.01;
  sdlqr::ArgParser parser(std::string(kProgram) + " export",
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

  sdlqr::logger::ExportOptions options;
  options.log_path = positional[0];
  options.out_dir = out;
  options.metrics.rate_command_period_s = period_s;
  options.progress = [](int percent, int64_t events) {
    std::cerr << kProgram << " export: " << percent << "% (" << events << " events)" << std::endl;
  };
  const sdlqr::logger::ExportResult result = sdlqr::logger::exportLog(options);
  const sdlqr::logger::LogFileStatus& log = result.log;
  if (log.truncated_tail_bytes > 0) {
    std::cerr << kProgram << " export: warning: '" << log.path << "' ends in a truncated event: "
              << log.truncated_tail_bytes << " bytes after byte " << log.readable_bytes
              << " unreadable (recorder killed?); exported the " << log.events << " readable events" << std::endl;
  }
  if (log.skipped_bytes > 0) {
    std::cerr << kProgram << " export: warning: '" << log.path << "' is damaged: skipped " << log.skipped_bytes
              << " bytes between events" << std::endl;
  }
  for (const sdlqr::logger::ExportedChannel& c : result.channels) {
    std::cout << "  " << c.channel << "  " << (c.lcm_type.empty() ? "(unknown type)" : c.lcm_type) << "  ";
    if (c.csv_path.empty()) std::cout << c.events << " events, not exported";
    else std::cout << c.rows << " rows -> " << c.csv_path;
    if (c.decode_failures > 0) std::cout << "  (" << c.decode_failures << " failed to decode)";
    std::cout << "\n";
  }
  std::cout << "  metrics -> " << result.metrics_path << std::endl;
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sdlqr::runMain(kProgram, [&]() {
    const std::string mode = argc >= 2 ? argv[1] : "";
    if (mode == "export") return runExport(argc - 1, argv + 1);
    if (mode == "record") return runRecord(argc - 1, argv + 1);
    return runRecord(argc, argv);
  });
}
