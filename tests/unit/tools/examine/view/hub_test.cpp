// The view hub: channels advertised with their generated schemas, the vehicle in Foxglove's
// schemas, only the newest message of a subscribed channel per frame, and a client that stops
// reading gets nothing queued.

#include <gtest/gtest.h>

#include <set>

#include "sdlqr/bus/convert.hpp"
#include "sdlqr/view/view_hub.hpp"

namespace sdlqr::view {
namespace {

struct Sink {
  std::vector<Outgoing> out;
  std::size_t buffered = 0;
  std::vector<Json> texts(const std::string& op) const {
    std::vector<Json> found;
    for (const Outgoing& o : out) {
      if (!o.binary && Json::parse(o.bytes)["op"] == op) found.push_back(Json::parse(o.bytes));
    }
    return found;
  }
  std::vector<const Outgoing*> frames() const {
    std::vector<const Outgoing*> found;
    for (const Outgoing& o : out) if (o.binary) found.push_back(&o);
    return found;
  }
};

template <class Plain>
void put(LatestStore& store, const std::string& channel, const Plain& plain, int64_t receive_utime) {
  const auto lcm = bus::toLcm(plain);
  std::string bytes(static_cast<std::size_t>(lcm.getEncodedSize()), '\0');
  lcm.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
  store.put(channel, sourceOf(channel, bytes.data(), bytes.size()), receive_utime, bytes.data(), bytes.size());
}

class Hub : public ::testing::Test {
 protected:
  void tick(double t) {
    hub.tick(t, [this](ClientId id) { return sinks[id].buffered; },
             [this](ClientId id, Outgoing&& o) { sinks[id].out.push_back(std::move(o)); });
  }
  uint32_t channelId(ClientId id, const std::string& topic) {
    for (const Json& a : sinks[id].texts("advertise")) {
      for (const Json& c : a["channels"]) if (c["topic"] == topic) return c["id"];
    }
    return 0;
  }
  // Client 1 connected and a SIM_TRUTH in the store, its channels advertised by a first tick.
  void connectToATruth(const SimTruth& truth) {
    hub.connect(1);
    put(store, "SIM_TRUTH", truth, 1);
    tick(0.0);
  }
  void subscribe(ClientId id, uint32_t channel, uint32_t subscription) {
    const Json request = {{"op", "subscribe"}, {"subscriptions", {{{"id", subscription}, {"channelId", channel}}}}};
    EXPECT_TRUE(hub.onText(id, request.dump()).empty());
  }

  LatestStore store;
  ViewHub hub{store, HubOptions{}};
  std::map<ClientId, Sink> sinks;
};

TEST_F(Hub, AdvertisesEachChannelWithItsSchemaAndTheVehicleInFoxglovesSchemas) {
  for (const Outgoing& o : hub.connect(1)) sinks[1].out.push_back(o);
  ASSERT_EQ(sinks[1].texts("serverInfo").size(), 1u);
  SimTruth truth;
  put(store, "QUAD1/SIM_TRUTH", truth, 1000);
  store.put("SOMEONE_ELSES", "", 0, "x", 1);
  tick(0.0);
  const std::vector<Json> adverts = sinks[1].texts("advertise");
  ASSERT_EQ(adverts.size(), 1u);
  std::map<std::string, std::string> schemas;
  for (const Json& c : adverts[0]["channels"]) schemas[c["topic"]] = c["schemaName"];
  EXPECT_EQ(schemas, (std::map<std::string, std::string>{{"QUAD1/SIM_TRUTH", "sdlqr.sim_truth_t"},
                                                         {"QUAD1/foxglove/truth_tf", "foxglove.FrameTransform"},
                                                         {"QUAD1/foxglove/scene", "foxglove.SceneUpdate"}}));
  EXPECT_EQ(hub.stats()["unknown_channels"]["SOMEONE_ELSES"], 1);
  // A later client gets every channel known so far at once.
  for (const Outgoing& o : hub.connect(2)) sinks[2].out.push_back(o);
  EXPECT_EQ(sinks[2].texts("advertise")[0]["channels"].size(), 3u);
}

TEST_F(Hub, AFrameCarriesOnlyTheNewestMessageOfEachSubscribedChannel) {
  SimTruth truth;
  connectToATruth(truth);
  const uint32_t channel = channelId(1, "SIM_TRUTH");
  ASSERT_NE(channel, 0u);
  subscribe(1, channel, 5);
  for (int i = 0; i < 50; ++i) {  // 50 messages between two frames
    truth.utime = i;
    put(store, "SIM_TRUTH", truth, 1000 + i);
  }
  tick(1.0);
  ASSERT_EQ(sinks[1].frames().size(), 1u);
  const std::string& frame = sinks[1].frames()[0]->bytes;
  EXPECT_EQ(frame[0], 0x01);
  EXPECT_EQ(static_cast<uint8_t>(frame[1]), 5);  // the subscription id
  EXPECT_EQ(Json::parse(frame.substr(13))["utime"], 49);
  tick(2.0);  // nothing new: nothing sent
  EXPECT_EQ(sinks[1].frames().size(), 1u);
}

TEST_F(Hub, AClientThatStopsReadingGetsNothingQueuedThenTheNewest) {
  SimTruth truth;
  connectToATruth(truth);
  subscribe(1, channelId(1, "SIM_TRUTH"), 1);
  sinks[1].buffered = 10u << 20;  // 10 MiB unsent: it stopped reading
  for (int i = 0; i < 600; ++i) {
    truth.utime = i;
    put(store, "SIM_TRUTH", truth, i);
    tick(1.0 + i / 60.0);
  }
  EXPECT_TRUE(sinks[1].frames().empty());
  EXPECT_GE(hub.stats()["clients"]["1"]["frames_skipped"], 599);
  sinks[1].buffered = 0;  // it reads again
  tick(20.0);
  ASSERT_EQ(sinks[1].frames().size(), 1u);
  EXPECT_EQ(Json::parse(sinks[1].frames()[0]->bytes.substr(13))["utime"], 599);
}

TEST_F(Hub, TheSceneOfAVehicleFollowsItsTruthAtItsOwnPace) {
  SimTruth truth;
  connectToATruth(truth);
  subscribe(1, channelId(1, "foxglove/scene"), 1);
  subscribe(1, channelId(1, "foxglove/truth_tf"), 2);
  for (int i = 1; i <= 60; ++i) {  // one second of ticks, the truth moving
    truth.position.x() = 0.1 * i;
    put(store, "SIM_TRUTH", truth, i);
    tick(i / 60.0);
  }
  int scenes = 0, transforms = 0;
  for (const Outgoing* f : sinks[1].frames()) (f->bytes[1] == 1 ? scenes : transforms) += 1;
  EXPECT_EQ(transforms, 60);
  EXPECT_GE(scenes, 4);  // every 0.2 s
  EXPECT_LE(scenes, 6);
}

TEST_F(Hub, EveryProcessBeatingInOneFrameIsSent) {
  hub.connect(1);
  HeartbeatRecord beat;
  beat.process = "sdlqr-gains";
  put(store, "HEARTBEAT", beat, 1);
  tick(0.0);
  subscribe(1, channelId(1, "HEARTBEAT"), 1);
  for (const char* process : {"sdlqr-gains", "sdlqr-sim", "sdlqr-estimator"}) {  // within one frame
    beat.process = process;
    put(store, "HEARTBEAT", beat, 2);
  }
  tick(1.0);
  std::set<std::string> sent;
  for (const Outgoing* f : sinks[1].frames()) sent.insert(Json::parse(f->bytes.substr(13))["process"].get<std::string>());
  EXPECT_EQ(sent, (std::set<std::string>{"sdlqr-gains", "sdlqr-sim", "sdlqr-estimator"}));
}

TEST_F(Hub, SubscribingToAnUnknownChannelIsAnsweredWithAStatus) {
  hub.connect(1);
  const std::vector<Outgoing> replies = hub.onText(1, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":99}]})");
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(Json::parse(replies[0].bytes)["op"], "status");
}

}  // namespace
}  // namespace sdlqr::view
