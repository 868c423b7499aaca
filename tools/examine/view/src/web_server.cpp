#include "sdlqr/view/web_server.hpp"

#define ASIO_STANDALONE
#include <websocketpp/config/asio_no_tls.hpp>
#include <websocketpp/server.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <thread>

#include "sdlqr/bus/wall_clock.hpp"

namespace sdlqr::view {

namespace {

using Server = websocketpp::server<websocketpp::config::asio>;
using Hdl = websocketpp::connection_hdl;
namespace fs = std::filesystem;

std::string contentType(const fs::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".html") return "text/html; charset=utf-8";
  if (ext == ".js") return "text/javascript; charset=utf-8";
  if (ext == ".css") return "text/css; charset=utf-8";
  if (ext == ".png") return "image/png";
  if (ext == ".svg") return "image/svg+xml";
  return "";
}

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read '" + path.string() + "'");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// "op=seek&value=12.5" -> the value of `key` ("" when absent).
std::string queryValue(const std::string& query, const std::string& key) {
  std::istringstream in(query);
  std::string pair;
  while (std::getline(in, pair, '&')) {
    const size_t eq = pair.find('=');
    if (pair.substr(0, eq) == key) return eq == std::string::npos ? "" : pair.substr(eq + 1);
  }
  return "";
}

}  // namespace

struct WebServer::Impl {
  struct StaticFile {
    std::string content_type;
    std::string body;
  };
  WebServerOptions options;
  ViewHub& hub;
  StatsSource stats;
  PlaybackControl control;
  asio::io_context io;
  Server server;
  std::unique_ptr<asio::steady_timer> timer;
  asio::steady_timer::time_point next_tick{};
  std::thread thread;
  std::future<void> finished;
  std::map<Hdl, ClientId, std::owner_less<Hdl>> ids;
  std::map<ClientId, Hdl> handles;
  ClientId next_id = 1;
  std::map<std::string, StaticFile> files;

  Impl(WebServerOptions o, ViewHub& h, StatsSource s, PlaybackControl c)
      : options(std::move(o)), hub(h), stats(std::move(s)), control(std::move(c)) {}

  void loadFiles();
  void configure();
  void onOpen(Hdl hdl);
  void onClose(Hdl hdl);
  void onMessage(Hdl hdl, const Server::message_ptr& message);
  void onHttp(Hdl hdl);
  void scheduleTick();
  void onTick();
  void sendTo(ClientId id, const Outgoing& out);
  std::size_t buffered(ClientId id);
};

void WebServer::Impl::loadFiles() {
  const fs::path root = options.web_root;
  if (!fs::is_regular_file(root / "index.html")) {
    throw std::runtime_error("--web-root: no index.html in '" + root.string() + "'");
  }
  for (const fs::directory_entry& entry : fs::directory_iterator(root)) {
    const std::string type = contentType(entry.path());
    if (entry.is_regular_file() && !type.empty()) {
      files["/" + entry.path().filename().string()] = {type, readFile(entry.path())};
    }
  }
  files["/"] = files["/index.html"];
  for (const char* rel : {"build/three.module.js", "build/three.core.js", "examples/jsm/controls/OrbitControls.js"}) {
    const fs::path path = fs::path(options.three_dir) / rel;
    if (!fs::is_regular_file(path)) {
      throw std::runtime_error("--three: no " + path.string() + " (the npm package three: run ./sdlqr setup)");
    }
    files[std::string("/vendor/three/") + rel] = {contentType(path), readFile(path)};
  }
}

void WebServer::Impl::configure() {
  server.clear_access_channels(websocketpp::log::alevel::all);
  server.clear_error_channels(websocketpp::log::elevel::all);
  server.set_error_channels(websocketpp::log::elevel::fatal);
  server.init_asio(&io);
  server.set_reuse_addr(true);
  server.set_max_message_size(1 << 20);     // a client sends subscribe/unsubscribe only
  server.set_max_http_body_size(64 << 10);  // and no HTTP body of any size
  // Once accepted (the socket is open then): a fixed kernel send buffer, which also turns off its
  // autotuning (up to 4 MiB here), so a stalled client backs up into the pacer's view at once.
  server.set_tcp_post_init_handler([this](Hdl hdl) {
    asio::error_code ec;
    asio::ip::tcp::socket& socket = server.get_con_from_hdl(hdl)->get_socket();
    socket.set_option(asio::socket_base::send_buffer_size(options.socket_send_buffer), ec);
    socket.set_option(asio::ip::tcp::no_delay(true), ec);
  });
  server.set_validate_handler([this](Hdl hdl) {
    Server::connection_ptr con = server.get_con_from_hdl(hdl);
    for (const std::string& protocol : con->get_requested_subprotocols()) {
      if (protocol == foxglove::kWebSocketSubprotocol) {
        con->select_subprotocol(protocol);
        return true;
      }
    }
    con->set_status(websocketpp::http::status_code::bad_request);
    con->set_body("WebSocket subprotocol foxglove.websocket.v1 required");
    return false;
  });
  server.set_open_handler([this](Hdl hdl) { onOpen(hdl); });
  server.set_close_handler([this](Hdl hdl) { onClose(hdl); });
  server.set_fail_handler([this](Hdl hdl) { onClose(hdl); });
  server.set_message_handler([this](Hdl hdl, Server::message_ptr m) { onMessage(hdl, m); });
  server.set_http_handler([this](Hdl hdl) { onHttp(hdl); });
  server.set_close_handshake_timeout(500);
  server.set_open_handshake_timeout(2000);
}

void WebServer::Impl::onOpen(Hdl hdl) {
  const ClientId id = next_id++;
  ids[hdl] = id;
  handles[id] = hdl;
  for (const Outgoing& out : hub.connect(id)) sendTo(id, out);
}

void WebServer::Impl::onClose(Hdl hdl) {
  const auto it = ids.find(hdl);
  if (it == ids.end()) return;
  hub.disconnect(it->second);
  handles.erase(it->second);
  ids.erase(it);
}

void WebServer::Impl::onMessage(Hdl hdl, const Server::message_ptr& message) {
  const auto it = ids.find(hdl);
  if (it == ids.end()) return;
  if (message->get_opcode() != websocketpp::frame::opcode::text) {
    sendTo(it->second, {false, foxglove::statusMessage(foxglove::StatusLevel::kError,
                                                       "binary client messages (client publishing) are not supported")});
    return;
  }
  for (const Outgoing& out : hub.onText(it->second, message->get_payload())) sendTo(it->second, out);
}

void WebServer::Impl::onHttp(Hdl hdl) {
  Server::connection_ptr con = server.get_con_from_hdl(hdl);
  const std::string resource = con->get_resource();
  const size_t q = resource.find('?');
  const std::string path = resource.substr(0, q);
  const std::string query = q == std::string::npos ? "" : resource.substr(q + 1);
  const std::string method = con->get_request().get_method();
  ApiReply reply{404, "{\"error\": \"not found\"}"};
  std::string type = "application/json";
  if (path == "/api/stats") {
    reply = {200, foxglove::dumpJson(stats())};
  } else if (path == "/api/playback") {
    reply = method == "POST" ? control(queryValue(query, "op"), queryValue(query, "value"))
                             : ApiReply{405, "{\"error\": \"POST /api/playback?op=play|pause|speed|seek&value=...\"}"};
  } else if (const auto file = files.find(path); file != files.end() && method == "GET") {
    reply = {200, file->second.body};
    type = file->second.content_type;
  }
  con->set_status(static_cast<websocketpp::http::status_code::value>(reply.first));
  con->append_header("Content-Type", type);
  con->append_header("Cache-Control", "no-store");
  con->set_body(reply.second);
}

// Ticks on a fixed grid, so the handler's own time does not stretch the period; after a stall the
// grid restarts from now rather than firing the missed ticks at once.
void WebServer::Impl::scheduleTick() {
  const auto period = std::chrono::duration_cast<asio::steady_timer::duration>(std::chrono::duration<double>(1.0 / options.tick_hz));
  const auto now = asio::steady_timer::clock_type::now();
  next_tick = next_tick + period < now ? now + period : next_tick + period;
  timer->expires_at(next_tick);
  timer->async_wait([this](const asio::error_code& ec) {
    if (ec) return;  // cancelled: stopping
    onTick();
    scheduleTick();
  });
}

void WebServer::Impl::onTick() {
  try {
    hub.tick(bus::monotonicSeconds(), [this](ClientId id) { return buffered(id); },
             [this](ClientId id, Outgoing&& out) { sendTo(id, out); });
  } catch (const std::exception& e) {
    std::cerr << "sdlqr-view: tick failed: " << e.what() << std::endl;
  }
}

std::size_t WebServer::Impl::buffered(ClientId id) {
  const auto it = handles.find(id);
  if (it == handles.end()) return 0;
  websocketpp::lib::error_code ec;
  Server::connection_ptr con = server.get_con_from_hdl(it->second, ec);
  return ec ? 0 : con->get_buffered_amount();
}

void WebServer::Impl::sendTo(ClientId id, const Outgoing& out) {
  const auto it = handles.find(id);
  if (it == handles.end()) return;
  websocketpp::lib::error_code ec;  // a connection closing under us: its close handler follows
  server.send(it->second, out.bytes.data(), out.bytes.size(),
              out.binary ? websocketpp::frame::opcode::binary : websocketpp::frame::opcode::text, ec);
}

WebServer::WebServer(WebServerOptions options, ViewHub& hub, StatsSource stats, PlaybackControl control)
    : impl_(std::make_unique<Impl>(std::move(options), hub, std::move(stats), std::move(control))) {}

WebServer::~WebServer() { stop(); }

void WebServer::start() {
  Impl& s = *impl_;
  s.loadFiles();
  s.configure();
  asio::error_code ec;
  const asio::ip::address address = asio::ip::make_address(s.options.address, ec);
  if (ec) throw std::runtime_error("--address: not an IP address: '" + s.options.address + "'");
  s.server.listen(asio::ip::tcp::endpoint(address, static_cast<unsigned short>(s.options.port)), ec);
  if (ec) throw std::runtime_error("cannot listen on " + url() + ": " + ec.message());
  s.server.start_accept();
  s.timer = std::make_unique<asio::steady_timer>(s.io);
  s.scheduleTick();
  std::packaged_task<void()> run([&s] {
    try {
      s.io.run();
    } catch (const std::exception& e) {
      std::cerr << "sdlqr-view: server stopped: " << e.what() << std::endl;
    }
  });
  s.finished = run.get_future();
  s.thread = std::thread(std::move(run));
}

void WebServer::stop() {
  Impl& s = *impl_;
  if (!s.thread.joinable()) return;
  asio::post(s.io, [&s] {
    s.timer->cancel();
    websocketpp::lib::error_code ec;
    s.server.stop_listening(ec);
    for (const auto& [id, hdl] : s.handles) s.server.close(hdl, websocketpp::close::status::going_away, "sdlqr-view stopping", ec);
  });
  // A client that stopped reading never completes its close handshake: its timeout ends it, and
  // after 2 s the loop is stopped whatever is left.
  if (s.finished.wait_for(std::chrono::seconds(2)) != std::future_status::ready) s.io.stop();
  s.thread.join();
}

std::string WebServer::url() const {
  const std::string& a = impl_->options.address;
  const bool v6 = a.find(':') != std::string::npos;
  return "http://" + (v6 ? "[" + a + "]" : a) + ":" + std::to_string(impl_->options.port) + "/";
}

}  // namespace sdlqr::view
