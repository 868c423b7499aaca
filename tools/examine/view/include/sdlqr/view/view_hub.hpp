#pragma once
// What sdlqr-view tells its WebSocket clients, without the sockets (web_server.hpp carries it):
// every channel of the store advertised in Foxglove's protocol (foxglove.websocket.v1) with the
// JSON Schema generated from its .lcm file, each vehicle's pose and scene in Foxglove's own
// schemas (tools/examine/foxglove/vehicle_scene.hpp), and, when a log plays, its playhead on
// "sdlqr/playback". Per client the subscriptions and a pacer: at each tick a client whose pacer
// allows a frame gets, for each channel it subscribed to, the newest message of each source
// (latest_store.hpp: each process on HEARTBEAT) it has not had yet; a backlogged client gets
// nothing (frames skipped, nothing queued). A message is encoded to JSON once per version,
// whatever the number of clients, and only when a client wants it.
// Not thread-safe: the server thread calls every method.

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/foxglove/vehicle_tracker.hpp"
#include "sdlqr/foxglove/ws_protocol.hpp"
#include "sdlqr/view/client_pacer.hpp"
#include "sdlqr/view/latest_store.hpp"

namespace sdlqr::view {

using Json = foxglove::Json;
using ClientId = uint64_t;

inline constexpr std::string_view kPlaybackTopic = "sdlqr/playback";

struct HubOptions {
  PacerLimits pacer;
  foxglove::VehicleGeometry geometry;
  double scene_period_s = 0.2;   // [s] between SceneUpdates of a vehicle (trails make them large)
  std::string name = "sdlqr-view";
  Json metadata = Json::object();  // serverInfo metadata, e.g. {"source": "live"}
};

struct Outgoing {
  bool binary = false;
  std::string bytes;
};

class ViewHub {
 public:
  ViewHub(LatestStore& store, HubOptions options) : store_(store), options_(std::move(options)) {}

  // The playhead of a log (published on sdlqr/playback when it changes); absent when live.
  void setPlaybackSource(std::function<Json()> state) { playback_source_ = std::move(state); }

  // A new client: the messages it gets first (serverInfo, then the channels known so far).
  std::vector<Outgoing> connect(ClientId id);
  void disconnect(ClientId id);
  // A text message from a client (subscribe, unsubscribe): the status replies.
  std::vector<Outgoing> onText(ClientId id, std::string_view text);
  // One tick at `now_s` [s, monotonic]: takes what changed in the store, advertises new channels
  // to every client, then sends each client its frame if its pacer allows one. `buffered(id)`:
  // the bytes that client's connection still holds unsent.
  void tick(double now_s, const std::function<std::size_t(ClientId)>& buffered,
            const std::function<void(ClientId, Outgoing&&)>& send);

  // Counters per client and of the hub, for /api/stats.
  Json stats() const;

 private:
  enum class Kind { kLcm, kTruthTf, kEstimateTf, kEstimatePose, kScene, kPlayback };
  // The newest message of one source of a channel.
  struct Slot {
    uint64_t version = 0;  // changes with its content
    int64_t stamp_ns = 0;  // the Message Data timestamp: receive time of the newest message
    std::vector<uint8_t> bytes;  // kLcm: the message as received
    uint64_t encoded_version = 0;
    std::string encoded;  // the JSON of encoded_version ("" : not one whole message)
  };
  struct Channel {
    foxglove::AdvertisedChannel advert;
    Kind kind = Kind::kLcm;
    std::string lcm_type;  // kLcm
    std::string vehicle;   // the derived kinds
    std::map<std::string, Slot> slots;  // per source; the derived kinds have one, ""
  };
  struct Client {
    foxglove::ClientSubscriptions subscriptions;
    ClientPacer pacer;
    std::map<std::pair<uint32_t, std::string>, uint64_t> sent_version;  // per channel id and source
  };
  struct Vehicle {
    foxglove::VehicleTracker tracker;
    double next_scene_s = 0.0;
    bool changed = false;
    uint64_t seek_count = 0;  // trails cleared when a log seek is seen
  };

  Channel& channel(const std::string& topic, Kind kind, std::vector<foxglove::AdvertisedChannel>* fresh);
  void ingest(StoredMessage& message, std::vector<foxglove::AdvertisedChannel>* fresh);
  void derive(const std::string& vehicle, foxglove::VehicleTracker::Update update, int64_t stamp_ns,
              std::vector<foxglove::AdvertisedChannel>* fresh);
  void updateScenes(double now_s, std::vector<foxglove::AdvertisedChannel>* fresh);
  void updatePlayback(std::vector<foxglove::AdvertisedChannel>* fresh);
  Slot& touch(Channel& c, int64_t stamp_ns, const std::string& source = {});
  const std::string& payload(Channel& c, Slot& slot);
  std::size_t sendFrame(ClientId id, Client& client, const std::function<void(ClientId, Outgoing&&)>& send);

  LatestStore& store_;
  HubOptions options_;
  std::function<Json()> playback_source_;
  std::string playback_text_;
  uint64_t seek_count_ = 0;
  uint64_t store_version_ = 0;
  std::vector<StoredMessage> updates_;
  std::map<uint32_t, Channel> channels_;
  std::map<std::string, uint32_t> by_topic_;
  std::map<std::string, Vehicle> vehicles_;
  std::map<ClientId, Client> clients_;
  std::map<std::string, uint64_t> unknown_channels_;  // heard, of no type of ours: not advertised
  uint64_t ticks_ = 0;
};

}  // namespace sdlqr::view
