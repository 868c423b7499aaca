// sdlqr-view: the bus (or a log) into the store, the store out to the browser and to Foxglove
// (view_hub.hpp through web_server.hpp, on the server's thread). The bus side listens only: the
// node never publishes, not even a HEARTBEAT.

#include <chrono>
#include <iostream>
#include <mutex>
#include <thread>

#include "sdlqr/bus/node.hpp"
#include "sdlqr/bus/wall_clock.hpp"
#include "sdlqr/view/view_cli.hpp"

using namespace sdlqr;
using namespace sdlqr::view;

namespace {

constexpr int kRawQueueCapacity = 4096;  // the bus thread only copies into the store: it keeps up

bool expired(const ViewCommand& command, double start) {
  return command.duration_s > 0.0 && bus::monotonicSeconds() - start >= command.duration_s;
}

int runLive(const ViewCommand& command) {
  LatestStore store;
  ViewHub hub(store, hubOptions(command, {{"source", "live"}}));
  const PlaybackControl no_playback = [](const std::string&, const std::string&) {
    return ApiReply{409, "{\"error\": \"live bus: no playback to control\"}"};
  };
  WebServer server(command.server, hub, viewStats(hub, store), no_playback);
  server.start();  // listening here, before the bus's namespace is joined
  if (!command.bus_netns.empty()) joinNetworkNamespace(command.bus_netns);
  bus::Node node(kViewProgram, command.bus);
  node.listenOnly();
  node.subscribeRaw(".*", [&store](const std::string& channel, const void* data, uint32_t size, int64_t receive_utime) {
    store.put(channel, sourceOf(channel, data, size), receive_utime, data, size);
  }, kRawQueueCapacity);
  std::cout << kViewProgram << ": live view of the bus at " << server.url() << std::endl;
  const double start = bus::monotonicSeconds();
  while (node.spin(50) && !expired(command, start)) {
  }
  server.stop();
  return 0;
}

int runLog(const ViewCommand& command) {
  LogPlayback playback;
  const logger::LogFileStatus status = loadLog(command.log_path, &playback);
  if (!status.complete()) {
    std::cerr << kViewProgram << ": warning: '" << status.path << "' is damaged or torn: playing its " << status.events
              << " readable events" << std::endl;
  }
  playback.setSpeed(command.speed);
  if (command.paused) playback.pause();
  LatestStore store;
  std::mutex mutex;
  ViewHub hub(store, hubOptions(command, {{"source", "log"}, {"log", command.log_path}}));
  hub.setPlaybackSource([&] {
    std::lock_guard<std::mutex> lock(mutex);
    return playback.state(command.log_path);
  });
  WebServer server(command.server, hub, viewStats(hub, store), playbackControl(playback, mutex, store, command.log_path));
  server.start();
  bus::installStopSignalHandlers();
  std::cout << kViewProgram << ": playing " << command.log_path << " (" << playback.events() << " events, "
            << playback.durationSeconds() << " s) at " << server.url() << std::endl;
  const double start = bus::monotonicSeconds();
  for (double last = start; !bus::stopRequested() && !expired(command, start);) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const double now = bus::monotonicSeconds();
    std::lock_guard<std::mutex> lock(mutex);
    playback.advance(now - last, store);
    last = now;
  }
  server.stop();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  return runMain(kViewProgram, [&] {
    const ViewCommand command = parseViewCommand(argc, argv);
    return command.log_path.empty() ? runLive(command) : runLog(command);
  });
}
