#pragma once
// The server side of Foxglove's WebSocket protocol, foxglove.websocket.v1, without the sockets:
// the JSON text messages the server sends (serverInfo, advertise, unadvertise, status), the
// binary Message Data frame, and one client's subscriptions, which its subscribe and unsubscribe
// messages change. Every channel carries JSON with a JSON Schema (schemaEncoding "jsonschema").
// A malformed or unknown client message is answered with a status message, never a crash or a
// disconnect.

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "sdlqr/foxglove/lcm_json.hpp"

namespace sdlqr::foxglove {

inline constexpr std::string_view kWebSocketSubprotocol = "foxglove.websocket.v1";

struct AdvertisedChannel {
  uint32_t id = 0;
  std::string topic;
  std::string schema_name;  // "sdlqr.imu_t", "foxglove.FrameTransform"
  std::string schema;       // the JSON Schema text
};

enum class StatusLevel { kInfo = 0, kWarning = 1, kError = 2 };

std::string serverInfoMessage(std::string_view name, const Json& metadata, std::string_view session_id);
std::string advertiseMessage(const std::vector<AdvertisedChannel>& channels);
std::string unadvertiseMessage(const std::vector<uint32_t>& channel_ids);
std::string statusMessage(StatusLevel level, std::string_view message);

// Appends one binary Message Data frame: opcode 0x01, uint32 subscription id, uint64 receive
// timestamp [ns], all little-endian, then the payload (the message's JSON).
void appendMessageData(std::string* frame, uint32_t subscription_id, uint64_t timestamp_ns, std::string_view payload);

class ClientSubscriptions {
 public:
  // Handles one text message from the client; returns the status messages to send back.
  // `advertised(channel_id)` tells whether the server advertises that channel.
  std::vector<std::string> onText(std::string_view text, const std::function<bool(uint32_t)>& advertised);
  // Channel id -> subscription id.
  const std::map<uint32_t, uint32_t>& byChannel() const { return by_channel_; }
  // The channel is gone (unadvertised): its subscription ends.
  void dropChannel(uint32_t channel_id);

 private:
  std::vector<std::string> subscribe(const Json& message, const std::function<bool(uint32_t)>& advertised);
  std::vector<std::string> unsubscribe(const Json& message);

  std::map<uint32_t, uint32_t> by_channel_;
  std::map<uint32_t, uint32_t> by_subscription_;  // subscription id -> channel id
};

}  // namespace sdlqr::foxglove
