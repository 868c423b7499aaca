#pragma once
// The command line of sdlqr-view, and the pieces its main binds together: the hub's options, the
// log a playback loads and the control of it, the network namespace of a private bus, /api/stats.

#include <mutex>
#include <string>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/logger/log_file_status.hpp"
#include "sdlqr/view/log_playback.hpp"
#include "sdlqr/view/web_server.hpp"

namespace sdlqr::view {

inline constexpr const char* kViewProgram = "sdlqr-view";

struct ViewCommand {
  ProcessOptions bus;           // --lcm-url, --bus-layout
  WebServerOptions server;      // --address, --port, --web-root, --three
  PacerLimits pacer;            // --max-rate, --max-client-buffer
  std::string log_path;         // --log: play this log instead of listening to the bus
  double speed = 1.0;           // --speed
  bool paused = false;          // --paused
  std::string bus_netns;        // --bus-netns: the bus's network namespace (a private flight's)
  double duration_s = 0.0;      // --duration: stop after this wall time (0: at SIGINT/SIGTERM)
};

// Exits 0 on --help and 2 on a bad option (ArgParser); throws std::invalid_argument naming the
// option whose value cannot be used.
ViewCommand parseViewCommand(int argc, const char* const* argv);

HubOptions hubOptions(const ViewCommand& command, Json metadata);

// /api/stats: the hub's counters, the store's, and this process's resident memory.
StatsSource viewStats(const ViewHub& hub, const LatestStore& store);

// POST /api/playback (on the server's thread) on a playback the main loop advances under `mutex`:
// play, pause, speed&value=F (0 < F <= 64), seek&value=S; the playhead as reply, 400 otherwise.
PlaybackControl playbackControl(LogPlayback& playback, std::mutex& mutex, LatestStore& store, std::string log_path);

// Reads every event of the log into `playback` (sorted, ready to play); throws logger::LogError
// when the log cannot be read or holds no event.
logger::LogFileStatus loadLog(const std::string& path, LogPlayback* playback);

// Moves the calling thread's network into the namespace of `path` (e.g. /proc/PID/ns/net): the
// bus sockets opened after it are that namespace's, the web server's listener opened before it
// stays in this one. Throws std::runtime_error naming the path when refused (needs root).
void joinNetworkNamespace(const std::string& path);

// VmRSS of this process [bytes], 0 when /proc cannot tell.
long residentBytes();

}  // namespace sdlqr::view
