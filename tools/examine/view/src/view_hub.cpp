#include "sdlqr/view/view_hub.hpp"

#include <algorithm>

#include "sdlqr/foxglove/foxglove_schemas.hpp"
#include "sdlqr/foxglove/lcm_json.hpp"
#include "sdlqr/logger/channel_types.hpp"

namespace sdlqr::view {

namespace {

// The JSON Schema of sdlqr/playback: the view's own status, not an LCM message.
const std::string& playbackSchema() {
  static const std::string text = foxglove::dumpJson({
      {"$schema", "http://json-schema.org/draft-07/schema#"},
      {"title", "sdlqr.view_playback"},
      {"description", "The playhead of the log sdlqr-view plays (./sdlqr view LOG)"},
      {"type", "object"},
      {"properties",
       {{"log", {{"type", "string"}, {"description", "the log's path"}}},
        {"position_s", {{"type", "number"}, {"description", "[s] playhead from the log's first event"}}},
        {"duration_s", {{"type", "number"}, {"description", "[s] first to last event"}}},
        {"speed", {{"type", "number"}, {"description", "[-] log time over wall time"}}},
        {"playing", {{"type", "boolean"}}},
        {"seek_count", {{"type", "integer"}, {"description", "[-] seeks so far: trails restart at each"}}},
        {"start_utime", {{"type", "integer"}, {"description", "[us] receive time of the first event"}}}}},
      {"required", Json::array({"position_s", "duration_s", "speed", "playing", "seek_count"})},
  });
  return text;
}

struct DerivedTopic {
  std::string_view name;
  std::string_view schema_name;
  std::string_view schema;
};

DerivedTopic derivedTopic(int kind) {
  switch (kind) {
    case 1: return {"truth_tf", "foxglove.FrameTransform", foxglove::kFrameTransformSchema};
    case 2: return {"estimate_tf", "foxglove.FrameTransform", foxglove::kFrameTransformSchema};
    case 3: return {"estimate_pose", "foxglove.PoseInFrame", foxglove::kPoseInFrameSchema};
    default: return {"scene", "foxglove.SceneUpdate", foxglove::kSceneUpdateSchema};
  }
}

Json pacerJson(const ClientPacer& pacer, std::size_t subscriptions) {
  const PacerCounters& c = pacer.counters();
  return {{"frames_sent", c.frames_sent}, {"frames_skipped", c.frames_skipped}, {"bytes_sent", c.bytes_sent},
          {"max_buffered_bytes", c.max_buffered_bytes}, {"subscriptions", subscriptions}};
}

}  // namespace

std::vector<Outgoing> ViewHub::connect(ClientId id) {
  clients_[id].pacer = ClientPacer(options_.pacer);
  std::vector<Outgoing> hello;
  hello.push_back({false, foxglove::serverInfoMessage(options_.name, options_.metadata, std::to_string(id))});
  std::vector<foxglove::AdvertisedChannel> all;
  for (const auto& [channel_id, c] : channels_) all.push_back(c.advert);
  if (!all.empty()) hello.push_back({false, foxglove::advertiseMessage(all)});
  return hello;
}

void ViewHub::disconnect(ClientId id) { clients_.erase(id); }

std::vector<Outgoing> ViewHub::onText(ClientId id, std::string_view text) {
  std::vector<Outgoing> replies;
  const auto it = clients_.find(id);
  if (it == clients_.end()) return replies;
  for (std::string& status : it->second.subscriptions.onText(text, [this](uint32_t c) { return channels_.count(c) > 0; })) {
    replies.push_back({false, std::move(status)});
  }
  return replies;
}

ViewHub::Channel& ViewHub::channel(const std::string& topic, Kind kind, std::vector<foxglove::AdvertisedChannel>* fresh) {
  const auto it = by_topic_.find(topic);
  if (it != by_topic_.end()) return channels_[it->second];
  const auto id = static_cast<uint32_t>(channels_.size() + 1);
  Channel& c = channels_[id];
  c.kind = kind;
  c.advert.id = id;
  c.advert.topic = topic;
  by_topic_[topic] = id;
  if (kind == Kind::kLcm) {
    c.lcm_type = std::string(logger::findChannelType(logger::splitChannel(topic).base)->lcm_type);
    const lcmtypes::JsonSchemaText* schema = foxglove::jsonSchemaOf(c.lcm_type);
    c.advert.schema_name = std::string(schema->name);
    c.advert.schema = std::string(schema->text);
  } else if (kind == Kind::kPlayback) {
    c.advert.schema_name = "sdlqr.view_playback";
    c.advert.schema = playbackSchema();
  } else {
    const DerivedTopic d = derivedTopic(static_cast<int>(kind));
    c.advert.schema_name = std::string(d.schema_name);
    c.advert.schema = std::string(d.schema);
  }
  fresh->push_back(c.advert);
  return c;
}

void ViewHub::ingest(StoredMessage& m, std::vector<foxglove::AdvertisedChannel>* fresh) {
  const logger::ChannelName split = logger::splitChannel(m.channel);
  if (logger::findChannelType(split.base) == nullptr) {
    ++unknown_channels_[m.channel];
    return;
  }
  Channel& c = channel(m.channel, Kind::kLcm, fresh);
  Slot& slot = touch(c, m.receive_utime * 1000, m.source);
  slot.bytes.swap(m.bytes);
  Vehicle& v = vehicles_[split.vehicle];
  const auto update = v.tracker.onMessage(split.base, slot.bytes.data(), slot.bytes.size());
  if (update != foxglove::VehicleTracker::Update::kNone) v.changed = true;
  derive(split.vehicle, update, slot.stamp_ns, fresh);
}

ViewHub::Slot& ViewHub::touch(Channel& c, int64_t stamp_ns, const std::string& source) {
  Slot& slot = c.slots[source];
  slot.stamp_ns = stamp_ns;
  ++slot.version;
  return slot;
}

void ViewHub::derive(const std::string& vehicle, foxglove::VehicleTracker::Update update, int64_t stamp_ns,
                     std::vector<foxglove::AdvertisedChannel>* fresh) {
  std::vector<Kind> kinds;
  if (update == foxglove::VehicleTracker::Update::kTruth) kinds = {Kind::kTruthTf};
  if (update == foxglove::VehicleTracker::Update::kEstimate) kinds = {Kind::kEstimateTf, Kind::kEstimatePose};
  for (Kind kind : kinds) {
    Channel& c = channel(foxglove::foxgloveTopic(vehicle, derivedTopic(static_cast<int>(kind)).name), kind, fresh);
    c.vehicle = vehicle;
    touch(c, stamp_ns);
  }
}

void ViewHub::updateScenes(double now_s, std::vector<foxglove::AdvertisedChannel>* fresh) {
  for (auto& [name, v] : vehicles_) {
    if (!v.changed || !v.tracker.state().truth || now_s < v.next_scene_s) continue;
    v.changed = false;
    v.next_scene_s = now_s + options_.scene_period_s;
    Channel& c = channel(foxglove::foxgloveTopic(name, "scene"), Kind::kScene, fresh);
    c.vehicle = name;
    touch(c, channels_[by_topic_[foxglove::foxgloveTopic(name, "truth_tf")]].slots[""].stamp_ns);
  }
}

void ViewHub::updatePlayback(std::vector<foxglove::AdvertisedChannel>* fresh) {
  if (!playback_source_) return;
  const Json state = playback_source_();
  std::string text = foxglove::dumpJson(state);
  if (text == playback_text_) return;
  playback_text_ = std::move(text);
  const uint64_t seeks = state.value("seek_count", uint64_t{0});
  if (seeks != seek_count_) {
    seek_count_ = seeks;
    for (auto& [name, v] : vehicles_) v.tracker.clearTrails();
  }
  Channel& c = channel(std::string(kPlaybackTopic), Kind::kPlayback, fresh);
  touch(c, state.value("start_utime", int64_t{0}) * 1000 + static_cast<int64_t>(state.value("position_s", 0.0) * 1e9));
}

const std::string& ViewHub::payload(Channel& c, Slot& slot) {
  std::string& out = slot.encoded;
  if (slot.encoded_version == slot.version) return out;
  slot.encoded_version = slot.version;
  out.clear();
  const foxglove::VehicleState* v = c.kind == Kind::kLcm || c.kind == Kind::kPlayback ? nullptr : &vehicles_[c.vehicle].tracker.state();
  switch (c.kind) {
    case Kind::kLcm:
      if (!foxglove::lcmBytesToJson(c.lcm_type, slot.bytes.data(), slot.bytes.size(), &out)) out.clear();
      break;
    case Kind::kTruthTf: out = foxglove::dumpJson(foxglove::truthTransform(*v->truth, c.vehicle, slot.stamp_ns)); break;
    case Kind::kEstimateTf:
      out = foxglove::dumpJson(foxglove::estimateTransform(*v->estimate, c.vehicle, slot.stamp_ns));
      break;
    case Kind::kEstimatePose: out = foxglove::dumpJson(foxglove::estimatePose(*v->estimate, slot.stamp_ns)); break;
    case Kind::kScene: out = foxglove::dumpJson(foxglove::sceneUpdate(*v, c.vehicle, options_.geometry, slot.stamp_ns)); break;
    case Kind::kPlayback: out = playback_text_; break;
  }
  return out;
}

void ViewHub::tick(double now_s, const std::function<std::size_t(ClientId)>& buffered,
                   const std::function<void(ClientId, Outgoing&&)>& send) {
  ++ticks_;
  std::vector<foxglove::AdvertisedChannel> fresh;
  store_version_ = store_.changedSince(store_version_, &updates_);
  for (StoredMessage& m : updates_) ingest(m, &fresh);
  updateScenes(now_s, &fresh);
  updatePlayback(&fresh);
  if (!fresh.empty()) {
    const std::string advertise = foxglove::advertiseMessage(fresh);
    for (const auto& [id, client] : clients_) send(id, {false, advertise});
  }
  for (auto& [id, client] : clients_) {
    if (client.pacer.onTick(now_s, buffered(id)) != ClientPacer::Decision::kSend) continue;
    client.pacer.sent(sendFrame(id, client, send));
  }
}

// The newest message of each source of each subscribed channel the client has not had; the
// frame's bytes.
std::size_t ViewHub::sendFrame(ClientId id, Client& client, const std::function<void(ClientId, Outgoing&&)>& send) {
  std::size_t bytes = 0;
  for (const auto& [channel_id, subscription_id] : client.subscriptions.byChannel()) {
    Channel& c = channels_[channel_id];
    for (auto& [source, slot] : c.slots) {
      uint64_t& sent = client.sent_version[{channel_id, source}];
      if (sent == slot.version) continue;
      sent = slot.version;
      const std::string& json = payload(c, slot);
      if (json.empty()) continue;
      Outgoing message{true, {}};
      message.bytes.reserve(13 + json.size());
      foxglove::appendMessageData(&message.bytes, subscription_id, static_cast<uint64_t>(std::max<int64_t>(0, slot.stamp_ns)), json);
      bytes += message.bytes.size();
      send(id, std::move(message));
    }
  }
  return bytes;
}

Json ViewHub::stats() const {
  Json clients = Json::object();
  for (const auto& [id, client] : clients_) {
    clients[std::to_string(id)] = pacerJson(client.pacer, client.subscriptions.byChannel().size());
  }
  Json unknown = Json::object();
  for (const auto& [name, count] : unknown_channels_) unknown[name] = count;
  return {{"ticks", ticks_}, {"channels", channels_.size()}, {"vehicles", vehicles_.size()},
          {"clients", clients}, {"unknown_channels", unknown},
          {"max_frame_rate_hz", options_.pacer.max_frame_rate_hz},
          {"max_buffered_bytes", options_.pacer.max_buffered_bytes}};
}

}  // namespace sdlqr::view
