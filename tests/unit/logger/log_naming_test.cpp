#include <gtest/gtest.h>

#include "sdlqr/logger/channel_types.hpp"
#include "sdlqr/lcmtypes/generated/descriptors.hpp"
#include "sdlqr/logger/log_naming.hpp"

namespace sdlqr::logger {
namespace {

TEST(LogNaming, DateAndScenarioInTheFileName) {
  std::tm t{};
  t.tm_year = 2024 - 1900;
  t.tm_mon = 4;
  t.tm_mday = 7;
  t.tm_hour = 9;
  t.tm_min = 5;
  t.tm_sec = 3;
  EXPECT_EQ(scenarioLogPath("runs", "hover_pull", t), "runs/20240507-090503-hover_pull.lcmlog");
  EXPECT_EQ(scenarioLogPath("runs/", "a", t), "runs/20240507-090503-a.lcmlog");
  EXPECT_EQ(scenarioLogPath("", "a", t), "./20240507-090503-a.lcmlog");
}

TEST(LogNaming, ScenarioNamesAreSafeFileNames) {
  EXPECT_EQ(invalidScenarioReason("step-x_2.5"), "");
  EXPECT_NE(invalidScenarioReason(""), "");
  EXPECT_NE(invalidScenarioReason("a/b"), "");
  EXPECT_NE(invalidScenarioReason("..hidden"), "");
  EXPECT_NE(invalidScenarioReason("with space"), "");
  EXPECT_NE(invalidScenarioReason(std::string(101, 'a')), "");
}

TEST(LogNaming, ChannelCsvPathsStayInsideTheExportFolder) {
  EXPECT_EQ(channelCsvPath("IMU"), "IMU.csv");
  EXPECT_EQ(channelCsvPath("QUAD1/IMU"), "QUAD1/IMU.csv");
  EXPECT_EQ(channelCsvPath("../../etc/passwd"), "_/_/etc/passwd.csv");
  EXPECT_EQ(channelCsvPath("/abs"), "_/abs.csv");
  EXPECT_EQ(channelCsvPath("A B*"), "A_B_.csv");
}

TEST(ChannelTypes, EveryGeneratedTypeHasExactlyOneChannel) {
  EXPECT_EQ(channelTypes().size(), std::size(lcmtypes::kAllTypes));
  for (const lcmtypes::TypeDescriptor* type : lcmtypes::kAllTypes) {
    int channels = 0;
    for (const ChannelType& c : channelTypes()) channels += c.lcm_type == type->name ? 1 : 0;
    EXPECT_EQ(channels, 1) << type->name;
  }
  ASSERT_NE(findChannelType("STATE_EST"), nullptr);
  EXPECT_EQ(findChannelType("STATE_EST")->lcm_type, "state_estimate_t");
  EXPECT_EQ(findChannelType("NOPE"), nullptr);
  const ChannelName split = splitChannel("QUAD1/RATE_CMD");
  EXPECT_EQ(split.vehicle, "QUAD1");
  EXPECT_EQ(split.base, "RATE_CMD");
  EXPECT_EQ(splitChannel("IMU").vehicle, "");
}

}  // namespace
}  // namespace sdlqr::logger
