// The bus layout as pure functions of the URL: which port each channel travels on, the URL
// arithmetic, and the set of URLs a recorder listens on. (Real multicast over several ports is
// the integration test bus_every_channel.)

#include <gtest/gtest.h>

#include <cstdlib>
#include <set>
#include <stdexcept>

#include "sdlqr/bus/bus_layout.hpp"
#include "sdlqr/messages/channels.hpp"

namespace sdlqr::bus {
namespace {

const std::string kBase = "udpm://239.255.76.67:7667?ttl=0";

TEST(BusLayout, HighRateChannelsHavePortsOfTheirOwn) {
  EXPECT_EQ(channelUrl(BusLayout::kSplit, kBase, "IMU"), "udpm://239.255.76.67:7668?ttl=0");
  EXPECT_EQ(channelUrl(BusLayout::kSplit, kBase, "MOTOR_CMD"), "udpm://239.255.76.67:7669?ttl=0");
  EXPECT_EQ(channelUrl(BusLayout::kSplit, kBase, "QUAD1/STATE_EST"), "udpm://239.255.76.67:7670?ttl=0");
  // The estimator's two inputs from one publisher share a port (their order is kept).
  EXPECT_EQ(channel::splitPortOffset(channel::kVioPose), channel::splitPortOffset(channel::kImu));
  // Everything else stays on the base port, ours or not.
  for (std::string_view name : {channel::kGains, channel::kCommand, channel::kTrajectory, channel::kParams,
                                channel::kDisturbance, channel::kHeartbeat}) {
    EXPECT_EQ(channelUrl(BusLayout::kSplit, kBase, name), kBase) << name;
  }
  EXPECT_EQ(channelUrl(BusLayout::kSplit, kBase, "LCM_SELF_TEST"), kBase);
  EXPECT_EQ(channelUrl(BusLayout::kSplit, kBase, "QUAD1/IMU/EXTRA"), kBase);
}

TEST(BusLayout, SingleLayoutPutsEveryChannelOnTheBase) {
  for (const ChannelInfo& entry : kChannels) {
    EXPECT_EQ(channelUrl(BusLayout::kSingle, kBase, entry.name), kBase);
  }
  EXPECT_EQ(layoutUrls(BusLayout::kSingle, kBase), std::vector<std::string>{kBase});
}

TEST(BusLayout, LayoutUrlsListEveryPortOnceBaseFirst) {
  const std::vector<std::string> urls = layoutUrls(BusLayout::kSplit, kBase);
  ASSERT_FALSE(urls.empty());
  EXPECT_EQ(urls.front(), kBase);
  EXPECT_EQ(std::set<std::string>(urls.begin(), urls.end()).size(), urls.size());
  // Every channel's URL is one of them: a recorder on these hears every channel.
  for (const ChannelInfo& entry : kChannels) {
    const std::string url = channelUrl(BusLayout::kSplit, kBase, entry.name);
    EXPECT_NE(std::find(urls.begin(), urls.end(), url), urls.end()) << entry.name;
  }
  EXPECT_EQ(urls.size(), 8u);
  // The monitor URL of sdlqr-bridge merge is none of them (it would forward forever).
  const std::string monitor = urlWithPortOffset(kBase, kMonitorPortOffset);
  EXPECT_EQ(std::find(urls.begin(), urls.end(), monitor), urls.end());
}

TEST(BusLayout, UrlArithmeticKeepsAddressAndOptions) {
  EXPECT_EQ(urlWithPortOffset("udpm://239.1.2.3:9000", 3), "udpm://239.1.2.3:9003");
  EXPECT_EQ(urlWithPortOffset("udpm://239.1.2.3?ttl=1&recv_buf_size=2097152", 1),
            "udpm://239.1.2.3:7668?ttl=1&recv_buf_size=2097152");
  EXPECT_EQ(urlWithPortOffset("udpm://", 0), "udpm://239.255.76.67:7667");
  EXPECT_EQ(urlWithPortOffset("udpm://:7000?ttl=0", 2), "udpm://239.255.76.67:7002?ttl=0");
  // The same port spelled two ways is one URL once normalized.
  EXPECT_EQ(layoutUrls(BusLayout::kSplit, "udpm://239.255.76.67?ttl=0").front(), kBase);
}

TEST(BusLayout, OtherProvidersAreLeftAlone) {
  EXPECT_FALSE(isUdpmUrl("memq://"));
  EXPECT_EQ(urlWithPortOffset("memq://", 5), "memq://");
  EXPECT_EQ(urlWithPortOffset("file:///tmp/x.lcmlog?mode=w", 5), "file:///tmp/x.lcmlog?mode=w");
}

TEST(BusLayout, MalformedUrlsAreRejectedNamingTheOption) {
  for (const char* bad : {"udpm://239.255.76.67:76x7", "udpm://239.255.76.67:", "udpm://239.255.76.67:123456"}) {
    try {
      urlWithPortOffset(bad, 1);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind("--lcm-url", 0), 0u) << e.what();
    }
  }
  EXPECT_THROW(layoutUrls(BusLayout::kSplit, "udpm://239.255.76.67:65530"), std::invalid_argument);
  EXPECT_NO_THROW(layoutUrls(BusLayout::kSingle, "udpm://239.255.76.67:65530"));
}

TEST(BusLayout, LayoutNamesParseOrNameTheOption) {
  EXPECT_EQ(parseBusLayout("single"), BusLayout::kSingle);
  EXPECT_EQ(parseBusLayout("split"), BusLayout::kSplit);
  EXPECT_STREQ(toString(BusLayout::kSplit), "split");
  try {
    parseBusLayout("Split");
    ADD_FAILURE() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--bus-layout", 0), 0u) << e.what();
  }
}

TEST(BusLayout, EmptyUrlResolvesAsLcmDoes) {
  ::unsetenv("LCM_DEFAULT_URL");
  EXPECT_EQ(resolveLcmUrl(""), kBase);
  ::setenv("LCM_DEFAULT_URL", "udpm://239.9.9.9:8000?ttl=0", 1);
  EXPECT_EQ(resolveLcmUrl(""), "udpm://239.9.9.9:8000?ttl=0");
  EXPECT_EQ(resolveLcmUrl("memq://"), "memq://");
  ::unsetenv("LCM_DEFAULT_URL");
}

}  // namespace
}  // namespace sdlqr::bus
