#include "sdlqr/foxglove/ws_protocol.hpp"

namespace sdlqr::foxglove {

namespace {

constexpr uint8_t kMessageDataOpcode = 0x01;

void appendLittleEndian(std::string* out, uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
}

// An unsigned 32-bit id member of `object`, or false.
bool idMember(const Json& object, const char* key, uint32_t* out) {
  const auto it = object.find(key);
  if (it == object.end() || !it->is_number_unsigned() || it->get<uint64_t>() > UINT32_MAX) return false;
  *out = static_cast<uint32_t>(it->get<uint64_t>());
  return true;
}

}  // namespace

std::string serverInfoMessage(std::string_view name, const Json& metadata, std::string_view session_id) {
  return dumpJson({{"op", "serverInfo"},
                   {"name", name},
                   {"capabilities", Json::array()},
                   {"supportedEncodings", Json::array({"json"})},
                   {"metadata", metadata},
                   {"sessionId", session_id}});
}

std::string advertiseMessage(const std::vector<AdvertisedChannel>& channels) {
  Json list = Json::array();
  for (const AdvertisedChannel& c : channels) {
    list.push_back({{"id", c.id},
                    {"topic", c.topic},
                    {"encoding", "json"},
                    {"schemaName", c.schema_name},
                    {"schema", c.schema},
                    {"schemaEncoding", "jsonschema"}});
  }
  return dumpJson({{"op", "advertise"}, {"channels", list}});
}

std::string unadvertiseMessage(const std::vector<uint32_t>& channel_ids) {
  return dumpJson({{"op", "unadvertise"}, {"channelIds", channel_ids}});
}

std::string statusMessage(StatusLevel level, std::string_view message) {
  return dumpJson({{"op", "status"}, {"level", static_cast<int>(level)}, {"message", message}});
}

void appendMessageData(std::string* frame, uint32_t subscription_id, uint64_t timestamp_ns, std::string_view payload) {
  frame->push_back(static_cast<char>(kMessageDataOpcode));
  appendLittleEndian(frame, subscription_id, 4);
  appendLittleEndian(frame, timestamp_ns, 8);
  frame->append(payload);
}

std::vector<std::string> ClientSubscriptions::onText(std::string_view text, const std::function<bool(uint32_t)>& advertised) {
  const Json message = Json::parse(text, nullptr, false);
  if (message.is_discarded() || !message.is_object()) {
    return {statusMessage(StatusLevel::kError, "not a JSON object: ignored")};
  }
  const auto op = message.find("op");
  if (op == message.end() || !op->is_string()) return {statusMessage(StatusLevel::kError, "message without \"op\": ignored")};
  if (*op == "subscribe") return subscribe(message, advertised);
  if (*op == "unsubscribe") return unsubscribe(message);
  return {statusMessage(StatusLevel::kWarning, "op \"" + op->get<std::string>() + "\" is not supported by this server")};
}

std::vector<std::string> ClientSubscriptions::subscribe(const Json& message, const std::function<bool(uint32_t)>& advertised) {
  const auto list = message.find("subscriptions");
  if (list == message.end() || !list->is_array()) {
    return {statusMessage(StatusLevel::kError, "subscribe: \"subscriptions\" must be an array")};
  }
  std::vector<std::string> replies;
  for (const Json& entry : *list) {
    uint32_t id = 0, channel = 0;
    if (!entry.is_object() || !idMember(entry, "id", &id) || !idMember(entry, "channelId", &channel)) {
      replies.push_back(statusMessage(StatusLevel::kError, "subscribe: each entry needs unsigned \"id\" and \"channelId\""));
    } else if (!advertised(channel)) {
      replies.push_back(statusMessage(StatusLevel::kError, "subscribe: channel " + std::to_string(channel) + " is not advertised"));
    } else if (by_subscription_.count(id) > 0) {
      replies.push_back(statusMessage(StatusLevel::kError, "subscribe: subscription id " + std::to_string(id) + " is in use"));
    } else if (by_channel_.count(channel) > 0) {
      replies.push_back(statusMessage(StatusLevel::kError, "subscribe: already subscribed to channel " + std::to_string(channel)));
    } else {
      by_channel_[channel] = id;
      by_subscription_[id] = channel;
    }
  }
  return replies;
}

std::vector<std::string> ClientSubscriptions::unsubscribe(const Json& message) {
  const auto list = message.find("subscriptionIds");
  if (list == message.end() || !list->is_array()) {
    return {statusMessage(StatusLevel::kError, "unsubscribe: \"subscriptionIds\" must be an array")};
  }
  std::vector<std::string> replies;
  for (const Json& entry : *list) {
    const bool valid = entry.is_number_unsigned() && entry.get<uint64_t>() <= UINT32_MAX;
    const auto it = valid ? by_subscription_.find(static_cast<uint32_t>(entry.get<uint64_t>())) : by_subscription_.end();
    if (it == by_subscription_.end()) {
      replies.push_back(statusMessage(StatusLevel::kWarning, "unsubscribe: no such subscription " + entry.dump()));
      continue;
    }
    by_channel_.erase(it->second);
    by_subscription_.erase(it);
  }
  return replies;
}

void ClientSubscriptions::dropChannel(uint32_t channel_id) {
  const auto it = by_channel_.find(channel_id);
  if (it == by_channel_.end()) return;
  by_subscription_.erase(it->second);
  by_channel_.erase(it);
}

}  // namespace sdlqr::foxglove
