// foxglove.websocket.v1, server side: what it sends, and one client's subscribe/unsubscribe,
// with every malformed message answered by a status, never a crash.

#include <gtest/gtest.h>

#include "mcap_reading.hpp"
#include "sdlqr/foxglove/ws_protocol.hpp"

namespace sdlqr::foxglove {
namespace {

const auto kAdvertised = [](uint32_t channel) { return channel == 1 || channel == 2; };

Json only(const std::vector<std::string>& replies) {
  EXPECT_EQ(replies.size(), 1u);
  return replies.empty() ? Json() : Json::parse(replies.front());
}

TEST(WsProtocol, ServerMessagesCarryTheFieldsOfTheProtocol) {
  const Json info = Json::parse(serverInfoMessage("sdlqr-view", {{"source", "live"}}, "7"));
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_EQ(info["supportedEncodings"], Json::array({"json"}));
  EXPECT_EQ(info["metadata"]["source"], "live");
  const Json advertise = Json::parse(advertiseMessage({{3, "IMU", "sdlqr.imu_t", "{}"}}));
  EXPECT_EQ(advertise["op"], "advertise");
  EXPECT_EQ(advertise["channels"][0]["id"], 3);
  EXPECT_EQ(advertise["channels"][0]["encoding"], "json");
  EXPECT_EQ(advertise["channels"][0]["schemaEncoding"], "jsonschema");
  EXPECT_EQ(Json::parse(unadvertiseMessage({3}))["channelIds"], Json::array({3}));
  EXPECT_EQ(Json::parse(statusMessage(StatusLevel::kWarning, "w"))["level"], 1);
}

TEST(WsProtocol, MessageDataIsOpcodeSubscriptionTimestampPayload) {
  std::string frame;
  appendMessageData(&frame, 0x01020304u, 0x1122334455667788ull, "{}");
  ASSERT_EQ(frame.size(), 1u + 4u + 8u + 2u);
  testing::Cursor c{frame};
  EXPECT_EQ(c.u8(), 0x01);
  EXPECT_EQ(c.u32(), 0x01020304u);
  EXPECT_EQ(c.u64(), 0x1122334455667788ull);
  EXPECT_EQ(c.take(2), "{}");
}

TEST(WsProtocol, SubscribeAndUnsubscribe) {
  ClientSubscriptions s;
  EXPECT_TRUE(s.onText(R"({"op":"subscribe","subscriptions":[{"id":10,"channelId":1},{"id":11,"channelId":2}]})", kAdvertised).empty());
  EXPECT_EQ(s.byChannel(), (std::map<uint32_t, uint32_t>{{1, 10}, {2, 11}}));
  EXPECT_TRUE(s.onText(R"({"op":"unsubscribe","subscriptionIds":[10]})", kAdvertised).empty());
  EXPECT_EQ(s.byChannel(), (std::map<uint32_t, uint32_t>{{2, 11}}));
  s.dropChannel(2);
  EXPECT_TRUE(s.byChannel().empty());
}

TEST(WsProtocol, EveryBadRequestGetsAStatusAndChangesNothing) {
  ClientSubscriptions s;
  ASSERT_TRUE(s.onText(R"({"op":"subscribe","subscriptions":[{"id":10,"channelId":1}]})", kAdvertised).empty());
  const std::pair<const char*, const char*> cases[] = {
      {"not json", "not a JSON object"},
      {"[1,2]", "not a JSON object"},
      {R"({"subscriptions":[]})", "without \"op\""},
      {R"({"op":"advertise","channels":[]})", "not supported"},
      {R"({"op":"subscribe","subscriptions":{}})", "must be an array"},
      {R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":2}]})", "unsigned"},
      {R"({"op":"subscribe","subscriptions":[{"id":12,"channelId":9}]})", "not advertised"},
      {R"({"op":"subscribe","subscriptions":[{"id":10,"channelId":2}]})", "in use"},
      {R"({"op":"subscribe","subscriptions":[{"id":12,"channelId":1}]})", "already subscribed"},
      {R"({"op":"subscribe","subscriptions":[{"id":99999999999,"channelId":2}]})", "unsigned"},
      {R"({"op":"unsubscribe","subscriptionIds":[77]})", "no such subscription"},
      {R"({"op":"unsubscribe","subscriptionIds":"x"})", "must be an array"},
  };
  for (const auto& [text, expected] : cases) {
    SCOPED_TRACE(text);
    const Json status = only(s.onText(text, kAdvertised));
    EXPECT_EQ(status["op"], "status");
    EXPECT_NE(status["message"].get<std::string>().find(expected), std::string::npos) << status.dump();
  }
  EXPECT_EQ(s.byChannel(), (std::map<uint32_t, uint32_t>{{1, 10}}));
}

}  // namespace
}  // namespace sdlqr::foxglove
