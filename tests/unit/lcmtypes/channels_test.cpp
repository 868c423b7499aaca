// A message type's channel is declared with the type (@channel NAME [Id], @split_port N): the
// generator writes the channel names, the Stream of each channel, the table of channels, each
// type's channel and the Outbox from them, and refuses a channel it cannot honour.

#include <gtest/gtest.h>

#include "schema_error.hpp"
#include "sdlqr/lcmgen/emit.hpp"

namespace sdlqr::lcmgen {
namespace {

std::string channelTypeText(const std::string& name, const std::string& plain, const std::string& channel) {
  return "package demo;\n// @plain " + plain + "\n" + channel + "\nstruct " + name +
         " {\n  int64_t utime;  // [us] time\n  int64_t seq;  // [-] sequence\n}\n";
}

struct ChannelHeaders {
  std::string channels, outbox;
};

ChannelHeaders generateChannels(const std::vector<std::string>& texts) {
  std::vector<LcmStruct> types;
  for (const std::string& text : texts) types.push_back(parseLcmStruct(text, "bad.lcm"));
  const PlainModel model = buildPlainModel(types);
  return {emitChannelsHeader(model, "test"), emitOutboxHeader(model, "test")};
}

void expectInHeader(const std::string& text, const std::string& fragment) {
  EXPECT_NE(text.find(fragment), std::string::npos) << "missing: " << fragment << "\nin:\n" << text;
}

TEST(Channels, EachTypeWithAChannelGetsItsNameStreamTableEntryAndOutboxOverload) {
  const ChannelHeaders g = generateChannels({channelTypeText("wind_estimate_t", "WindEstimate", "// @channel WIND_EST @split_port 9"),
                                channelTypeText("rate_cmd_t", "RateCommand", "// @channel RATE_CMD RateCommand"),
                                channelTypeText("note_t", "Note", "")});
  expectInHeader(g.channels, "inline constexpr std::string_view kWindEstimate = \"WIND_EST\";  // wind_estimate_t");
  expectInHeader(g.channels, "inline constexpr std::string_view kRateCommand = \"RATE_CMD\";  // rate_cmd_t");
  expectInHeader(g.channels, "enum class Stream : int8_t {\n  kWindEstimate,\n  kRateCommand,\n  kOther,\n  kCount\n};");
  expectInHeader(g.channels, "{channel::kWindEstimate, Stream::kWindEstimate, \"wind_est\", \"wind_estimate_t\", 9},");
  expectInHeader(g.channels, "{channel::kRateCommand, Stream::kRateCommand, \"rate_cmd\", \"rate_cmd_t\", 0},");
  expectInHeader(g.channels, "struct MessageChannel<WindEstimate> {\n  static constexpr std::string_view kName = channel::kWindEstimate;");
  expectInHeader(g.channels, "using ChannelTypes = MessageTypes<WindEstimate, RateCommand>;");
  expectInHeader(g.outbox, "  virtual void publish(const WindEstimate& m) = 0;\n  virtual void publish(const RateCommand& m) = 0;\n};");
  expectInHeader(g.outbox, "  void publish(const RateCommand& m) override { sink_(m); }");
  // A type without @channel travels on no channel of its own.
  EXPECT_EQ(g.channels.find("Note"), std::string::npos);
  EXPECT_EQ(g.outbox.find("Note"), std::string::npos);
}

TEST(Channels, AChannelTheGeneratorCannotHonourIsOneErrorNamingTheFile) {
  const auto refused = [](const std::vector<std::string>& texts, const std::string& fragment) {
    test::expectSchemaError([&] { generateChannels(texts); }, fragment, texts.front());
  };
  refused({channelTypeText("a_t", "A", "// @channel lower_case")}, "@channel needs an UPPER_SNAKE name");
  refused({channelTypeText("a_t", "A", "// @channel")}, "@channel needs an UPPER_SNAKE name");
  refused({channelTypeText("a_t", "A", "// @split_port 2")}, "@split_port without @channel");
  refused({channelTypeText("a_t", "A", "// @channel A @split_port 0")}, "@split_port needs a port offset from 1 to 999");
  refused({channelTypeText("a_t", "A", "// @channel A @split_port x")}, "@split_port needs a port offset from 1 to 999");
  refused({channelTypeText("a_t", "A", "// @channel SAME"), channelTypeText("b_t", "B", "// @channel SAME")},
          "@channel SAME is another type's channel");
  refused({channelTypeText("a_t", "A", "// @channel ONE Id"), channelTypeText("b_t", "B", "// @channel TWO Id")},
          "@channel identifier Id is another channel's");
}

}  // namespace
}  // namespace sdlqr::lcmgen
