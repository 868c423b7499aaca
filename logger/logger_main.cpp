// sdlqr-logger: records the bus to an LCM event log through the logger's core
// (logger/logger_core.hpp), and exports a log to CSV + metrics.json (logger_cli.hpp).

#include <chrono>
#include <iostream>

#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/wall_clock.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/logger/logger_cli.hpp"
#include "sdlqr/logger/logger_core.hpp"

using namespace sdlqr;
using logger::kLoggerProgram;

namespace {

constexpr int kRawQueueCapacity = 10000;  // LCM-side queue; our handler empties it quickly

int runRecord(int argc, const char* const* argv) {
  const logger::RecordCommand command = logger::parseRecordCommand(argc, argv);
  logger::LoggerCore core(command.recorder);
  bus::Node node(kLoggerProgram, command.process, core.health());
  node.subscribeRaw(command.pattern, [&](const std::string& channel, const void* data, uint32_t size,
                                         int64_t receive_utime) { core.onMessage(channel, data, size, receive_utime); },
                    kRawQueueCapacity);
  std::cout << kLoggerProgram << ": recording '" << command.pattern << "'"
            << (command.scenario.empty() ? "" : " (scenario " + command.scenario + ")") << " to "
            << core.recorder().path() << std::endl;
  const double stop_at = command.duration_s > 0.0 ? bus::monotonicSeconds() + command.duration_s : -1.0;
  while (node.spin(50) && (stop_at < 0.0 || bus::monotonicSeconds() < stop_at)) core.onWallTime(bus::monotonicSeconds());
  // Record our own last heartbeat (final counters, STOPPING) before closing the file.
  core.onWallTime(1e300);
  node.shutdown();
  const auto drain_until = std::chrono::steady_clock::now() + std::chrono::milliseconds(200);
  while (std::chrono::steady_clock::now() < drain_until) node.drain(20);
  core.stop();
  return logger::reportRecording(core.recorder().stats(), core.recorder().path());
}

}  // namespace

int main(int argc, char** argv) {
  return runMain(kLoggerProgram, [&]() {
    const std::string mode = argc >= 2 ? argv[1] : "";
    if (mode == "export") return logger::runExportCommand(argc - 1, argv + 1);
    if (mode == "record") return runRecord(argc - 1, argv + 1);
    return runRecord(argc, argv);
  });
}
