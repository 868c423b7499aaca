#include "sdlqr/view/view_cli.hpp"

#include <fcntl.h>
#include <sched.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "sdlqr/logger/log_reader.hpp"

namespace sdlqr::view {

ViewCommand parseViewCommand(int argc, const char* const* argv) {
  ViewCommand c;
  c.server.web_root = SDLQR_VIEW_WEB_ROOT;
  c.server.three_dir = SDLQR_VIEW_THREE_DIR;
  double max_buffer_kib = static_cast<double>(c.pacer.max_buffered_bytes) / 1024.0;
  ArgParser parser(kViewProgram,
                   "Watch flights in the browser: serves a page with the vehicles in 3D (three.js), strip charts\n"
                   "and each process's health, and speaks Foxglove's WebSocket protocol (foxglove.websocket.v1)\n"
                   "on the same port: every channel as JSON with its JSON Schema, each vehicle's pose and scene in\n"
                   "Foxglove's own schemas. Listens to every channel of every vehicle and never publishes on the\n"
                   "bus; with --log it plays a recorded flight instead (play, pause, speed, seek). Keeps only the\n"
                   "newest message per channel and sends a client at most --max-rate frames a second, none while\n"
                   "its connection holds more than --max-client-buffer unsent (docs/view.md).");
  parser.addOption("--address", &c.server.address, "IP", "address to serve on (default 127.0.0.1: this machine only)");
  parser.addOption("--port", &c.server.port, "N", "TCP port (default 8080)", Range::closed(1, 65535));
  parser.addOption("--log", &c.log_path, "FILE", "play this LCM log instead of listening to the bus");
  parser.addOption("--speed", &c.speed, "F", "with --log: log seconds per wall second (default 1)", Range::openClosed(0, 64));
  parser.addFlag("--paused", &c.paused, "with --log: start paused");
  addLcmUrlOption(parser, &c.bus.lcm_url);
  addBusLayoutOption(parser, &c.bus);
  parser.addOption("--bus-netns", &c.bus_netns, "FILE",
                   "listen to the bus of this network namespace (e.g. /proc/PID/ns/net of a private flight)\n"
                   "while serving in this one (needs root)");
  parser.addOption("--max-rate", &c.pacer.max_frame_rate_hz, "HZ", "frames a second per client, at most (default 60)",
                   Range::openClosed(0, 60));
  parser.addOption("--max-client-buffer", &max_buffer_kib, "KIB",
                   "skip a client's frames while its connection holds more unsent (default 1024)", Range::atLeast(1));
  parser.addOption("--web-root", &c.server.web_root, "DIR", "the page's files (default: tools/examine/view/web of the source)");
  parser.addOption("--three", &c.server.three_dir, "DIR", "the npm package three (default: node_modules/three)");
  parser.addOption("--duration", &c.duration_s, "S", "stop after S seconds of wall time (default: at SIGINT/SIGTERM)",
                   Range::atLeast(0));
  parser.setEpilog("exit codes: 0 stopped, 1 the server failed, 2 bad option or unreadable log");
  parser.parseOrExit(argc, argv);
  c.pacer.max_buffered_bytes = static_cast<std::size_t>(max_buffer_kib * 1024.0);
  c.server.tick_hz = c.pacer.max_frame_rate_hz;
  if (!c.log_path.empty() && !c.bus_netns.empty()) throw std::invalid_argument("--bus-netns: not with --log (no bus)");
  return c;
}

HubOptions hubOptions(const ViewCommand& command, Json metadata) {
  HubOptions options;
  options.pacer = command.pacer;
  options.metadata = std::move(metadata);
  return options;
}

StatsSource viewStats(const ViewHub& hub, const LatestStore& store) {
  return [&hub, &store] {
    const StoreStats s = store.stats();
    return Json{{"hub", hub.stats()}, {"resident_bytes", residentBytes()},
                {"store", {{"puts", s.puts}, {"slots", s.slots}, {"refused_slots", s.refused_slots},
                           {"refused_size", s.refused_size}}}};
  };
}

PlaybackControl playbackControl(LogPlayback& playback, std::mutex& mutex, LatestStore& store, std::string log_path) {
  return [&playback, &mutex, &store, log = std::move(log_path)](const std::string& op, const std::string& value) -> ApiReply {
    std::lock_guard<std::mutex> lock(mutex);
    char* end = nullptr;
    const double number = std::strtod(value.c_str(), &end);
    const bool numeric = !value.empty() && end != nullptr && *end == '\0';
    bool done = true;
    if (op == "play") playback.play();
    else if (op == "pause") playback.pause();
    else if (op == "speed") done = numeric && playback.setSpeed(number);
    else if (op == "seek" && numeric) playback.seek(number, store);
    else done = false;
    if (!done) return {400, "{\"error\": \"op: play, pause, speed&value=F (0 < F <= 64) or seek&value=S\"}"};
    return {200, foxglove::dumpJson(playback.state(log))};
  };
}

logger::LogFileStatus loadLog(const std::string& path, LogPlayback* playback) {
  logger::LogReader reader(path);
  logger::LogEvent event;
  while (reader.next(&event)) playback->add(event.channel, event.receive_utime, event.data, static_cast<std::size_t>(event.size));
  if (playback->events() == 0) throw logger::LogError("'" + path + "' holds no LCM event");
  playback->finishLoading();
  return reader.status();
}

void joinNetworkNamespace(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error("--bus-netns: cannot open '" + path + "': " + std::strerror(errno));
  const int status = ::setns(fd, CLONE_NEWNET);
  const int error = errno;
  ::close(fd);
  if (status != 0) throw std::runtime_error("--bus-netns: cannot join '" + path + "': " + std::strerror(error));
}

long residentBytes() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      long kib = 0;
      status >> kib;
      return kib * 1024;
    }
    status.ignore(4096, '\n');
  }
  return 0;
}

}  // namespace sdlqr::view
