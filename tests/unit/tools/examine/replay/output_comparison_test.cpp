// compareOutputs: bit-for-bit equality, tolerance, the first difference and per-field maxima.

#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/replay/output_comparison.hpp"

namespace sdlqr::replay {
namespace {

RecordedFlight recording() {
  RecordedFlight f;
  for (int i = 0; i < 5; ++i) {
    RateCommand r;
    r.seq = i;
    r.utime = 10'000 * i;
    r.body_rate = Vec3(0.1 * i, -0.2, 0.3);
    r.thrust = 9.81 + 0.01 * i;
    f.rate_command.push_back(r);
    GainSet g;
    g.seq = i;
    g.K.setConstant(1.0 + i);
    g.solve_us = 50.0 + i;
    f.gains.push_back(g);
  }
  return f;
}

ReplayOutputs outputsOf(const RecordedFlight& f) {
  ReplayOutputs o;
  o.rate_command = f.rate_command;
  o.gains = f.gains;
  return o;
}

TEST(OutputComparison, IdenticalOutputsAreBitForBitAndSolveTimeIsNotCompared) {
  const RecordedFlight f = recording();
  ReplayOutputs o = outputsOf(f);
  for (GainSet& g : o.gains) g.solve_us = 0.0;  // wall time: differs on every run
  const Comparison c = compareOutputs(f, o, 0.0);
  EXPECT_TRUE(c.bitForBit()) << formatComparison(c);
  EXPECT_NE(formatComparison(c).find("every output identical bit for bit"), std::string::npos);
}

TEST(OutputComparison, ReportsTheFirstDifferenceAndTheLargestPerField) {
  const RecordedFlight f = recording();
  ReplayOutputs o = outputsOf(f);
  o.rate_command[2].thrust += 1e-13;
  o.rate_command[3].thrust += 4e-13;
  o.rate_command[3].body_rate[1] = std::nextafter(o.rate_command[3].body_rate[1], 0.0);
  o.gains[4].K(3, 9) += 2e-14;

  const Comparison exact = compareOutputs(f, o, 0.0);
  const std::string text = formatComparison(exact);
  std::cout << text;
  EXPECT_FALSE(exact.bitForBit());
  EXPECT_FALSE(exact.withinTolerance());
  const ChannelComparison& rate = exact.channels[1];
  ASSERT_EQ(rate.channel, "RATE_CMD");
  EXPECT_EQ(rate.compared, 5);
  EXPECT_EQ(rate.identical, 3);
  EXPECT_EQ(rate.first_difference.rfind("RATE_CMD seq 2 thrust: recorded ", 0), 0u) << rate.first_difference;
  ASSERT_EQ(rate.fields.size(), 2u);
  EXPECT_EQ(rate.fields[0].field, "body_rate[1]");
  EXPECT_EQ(rate.fields[0].messages, 1);
  EXPECT_EQ(rate.fields[1].field, "thrust");
  EXPECT_EQ(rate.fields[1].messages, 2);
  EXPECT_NEAR(rate.fields[1].max_abs, 4e-13, 1e-15);
  const ChannelComparison& gains = exact.channels[3];
  EXPECT_EQ(gains.fields.at(0).field, "K[39]");
  EXPECT_NE(text.find("GAINS.K[39]"), std::string::npos);

  const Comparison loose = compareOutputs(f, o, 1e-12);
  EXPECT_FALSE(loose.bitForBit());
  EXPECT_TRUE(loose.withinTolerance());
  EXPECT_NE(formatComparison(loose).find("every difference within 1e-12"), std::string::npos);
}

TEST(OutputComparison, MissingAndExtraMessagesAreDifferences) {
  RecordedFlight f = recording();
  ReplayOutputs o = outputsOf(f);
  o.rate_command.erase(o.rate_command.begin() + 1);  // seq 1: recorded, not recomputed
  f.rate_command.erase(f.rate_command.begin() + 2);  // seq 2: recomputed, not in the recording
  const Comparison c = compareOutputs(f, o, 1.0);
  const ChannelComparison& rate = c.channels[1];
  EXPECT_EQ(rate.only_recorded, 1);
  EXPECT_EQ(rate.only_replayed, 1);
  EXPECT_EQ(rate.after_recording, 0);
  EXPECT_FALSE(c.withinTolerance());
  EXPECT_EQ(rate.first_difference, "RATE_CMD seq 1: recorded, not recomputed");
}

// The replayed controller ticks once past the recorded flight's last RATE_CMD (seq 5).
void tickOnceMore(ReplayOutputs& o) {
  RateCommand extra = o.rate_command.back();
  extra.seq = 5;
  o.rate_command.push_back(extra);
}

// The recorder stops a moment before the processes do: what the replay computes past a channel's
// last recorded message is reported, not a difference. A channel with nothing recorded is.
TEST(OutputComparison, MessagesRecomputedAfterTheRecordingEndedAreNotDifferences) {
  const RecordedFlight f = recording();
  ReplayOutputs o = outputsOf(f);
  tickOnceMore(o);
  const Comparison c = compareOutputs(f, o, 0.0);
  const ChannelComparison& rate = c.channels[1];
  ASSERT_EQ(rate.channel, "RATE_CMD");
  EXPECT_EQ(rate.after_recording, 1);
  EXPECT_EQ(rate.only_replayed, 0);
  EXPECT_TRUE(c.bitForBit());
  EXPECT_NE(formatComparison(c).find("RATE_CMD: 1 recomputed after the recording ended"), std::string::npos);

  RecordedFlight no_gains = f;
  no_gains.gains.clear();
  const Comparison without = compareOutputs(no_gains, o, 0.0);
  for (const ChannelComparison& ch : without.channels) {
    if (ch.channel == "GAINS") {
      EXPECT_EQ(ch.only_replayed, 5);
    }
  }
  EXPECT_FALSE(without.bitForBit());
}

// A foreign publisher's RATE_CMD in the recording (a rogue's, seq 1000000) is recorded only and
// does not move the recording's end: the replay's tick past the controller's last recorded one is
// still after the recording, and a tick missing in the middle is still a difference.
TEST(OutputComparison, AForeignRecordedMessageDoesNotMoveTheRecordingsEnd) {
  RecordedFlight f = recording();
  ReplayOutputs o = outputsOf(f);
  RateCommand rogue = f.rate_command.back();
  rogue.seq = 1000000;
  f.rate_command.push_back(rogue);
  tickOnceMore(o);
  const Comparison whole = compareOutputs(f, o, 0.0);
  const ChannelComparison& rate = whole.channels[1];
  ASSERT_EQ(rate.channel, "RATE_CMD");
  EXPECT_EQ(rate.only_recorded, 1);
  EXPECT_EQ(rate.after_recording, 1);
  EXPECT_EQ(rate.only_replayed, 0);

  f.rate_command.erase(f.rate_command.begin() + 2);  // seq 2: recomputed, not in the recording
  const Comparison with_gap = compareOutputs(f, o, 0.0);
  const ChannelComparison& gap = with_gap.channels[1];
  EXPECT_EQ(gap.only_replayed, 1);
  EXPECT_EQ(gap.after_recording, 1);
}

}  // namespace
}  // namespace sdlqr::replay
