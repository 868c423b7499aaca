#pragma once
// sdlqr-view's HTTP and WebSocket server (Debian's websocketpp on standalone asio), on a thread of
// its own so the bus thread only ever copies a message into the store:
//   GET /                      the page (web/index.html), its scripts and styles from web_root,
//   GET /vendor/three/...      three.js from node_modules (installed by ./sdlqr setup, no CDN),
//   GET /api/stats             the hub's and the caller's counters (JSON),
//   POST /api/playback?op=..   play, pause, speed&value=F, seek&value=S (a log; 409 when live),
//   WebSocket (subprotocol foxglove.websocket.v1) the view hub's channels.
// Files are read once at start; a request for any other path is a 404, so nothing outside those
// folders is served. Every tick (1/max_frame_rate) the hub sends each client what its pacer allows.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "sdlqr/view/view_hub.hpp"

namespace sdlqr::view {

struct WebServerOptions {
  std::string address = "127.0.0.1";
  int port = 8080;
  std::string web_root;   // the page: index.html and its .js and .css files
  std::string three_dir;  // the npm package three (build/ and examples/jsm/controls/)
  double tick_hz = 60.0;  // [1/s] hub ticks
  int socket_send_buffer = 64 * 1024;  // [bytes] kernel send buffer per client (the kernel doubles it)
};

// An HTTP reply: status code and JSON body.
using ApiReply = std::pair<int, std::string>;
// op and value of POST /api/playback.
using PlaybackControl = std::function<ApiReply(const std::string& op, const std::string& value)>;
using StatsSource = std::function<Json()>;

class WebServer {
 public:
  WebServer(WebServerOptions options, ViewHub& hub, StatsSource stats, PlaybackControl control);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  // Reads the files, binds and starts the thread; throws std::runtime_error naming what failed
  // (a missing file, an address in use).
  void start();
  // Closes every connection and joins the thread (also done by the destructor).
  void stop();
  std::string url() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace sdlqr::view
