#include <regex.h>

#include <ctime>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <string>

#include "sdlqr/logger/log_naming.hpp"
#include "sdlqr/logger/logger_cli.hpp"

namespace sdlqr::logger {

namespace {

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
  const std::string reason = invalidScenarioReason(name);
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
  return scenarioLogPath(folder, name, local);
}

}  // namespace

RecordCommand parseRecordCommand(int argc, const char* const* argv) {
  RecordCommand command;
  sdlqr::ProcessOptions& process = command.process;
  std::string out;
  std::string dir;
  std::string& scenario = command.scenario;
  std::string channels;
  double& duration_s = command.duration_s;
  sdlqr::ArgParser parser(std::string(kLoggerProgram) + " [record]",
                          "Records every LCM channel (or those matching --channels) to a standard LCM event log,\n"
                          "readable by lcm-logplayer. Flushes at least every 0.2 s; stops on SIGINT/SIGTERM or\n"
                          "after --duration, with everything written. Never overwrites a file.");
  parser.addOption("--out", &out, "FILE", "log file to create (its folder is created if missing)");
  parser.addOption("--dir", &dir, "DIR", "folder for <YYYYmmdd-HHMMSS>-<scenario>.lcmlog (default: .)");
  parser.addOption("--scenario", &scenario, "NAME", "scenario part of the file name (default: flight)");
  parser.addOption("--channels", &channels, "REGEX",
                   "channels to record, LCM regex on the full name (default: all; with --vehicle, PREFIX/.*)");
  parser.addOption("--duration", &duration_s, "S", "stop after S seconds of wall time (default: until a signal)",
                   sdlqr::Range::atLeast(0));
  sdlqr::addLcmUrlOption(parser, &process.lcm_url);
  parser.addOption("--vehicle", &process.vehicle, "PREFIX", "vehicle to record; also prefixes this logger's HEARTBEAT");
  sdlqr::addBusLayoutOption(parser, &process);
  parser.setEpilog(
      "Other mode: sdlqr-logger export LOG --out DIR   (CSV per channel + metrics.json; see export --help)\n\n"
      "exit codes: 0 recorded, 1 write errors or fatal error, 2 bad arguments or the file exists");
  parser.parseOrExit(argc, argv);
  command.pattern = !channels.empty() ? channels : (process.vehicle.empty() ? ".*" : process.vehicle + "/.*");
  checkChannelRegex(command.pattern);
  command.recorder.path = logPath(out, dir, scenario);
  return command;
}

int reportRecording(const RecorderStats& s, const std::string& path) {
  std::cout << kLoggerProgram << ": wrote " << s.written << " messages (" << s.bytes_written << " bytes) to " << path
            << "; dropped " << s.dropped << ", write errors " << s.write_errors << std::endl;
  if (s.write_errors == 0) return 0;
  std::cerr << kLoggerProgram << ": " << s.last_error << "\n";
  return 1;
}

}  // namespace sdlqr::logger


