// The mission's re-send of its current setpoint command (for a controller restarted mid-flight).

#include <gtest/gtest.h>

#include "sdlqr/mission/command_resender.hpp"

namespace sdlqr::mission {
namespace {

Command sentAt(int64_t utime, int64_t seq, CommandType type, double z = 1.0) {
  Command c;
  c.utime = utime;
  c.seq = seq;
  c.command = type;
  c.position = Vec3(0.0, 0.0, z);
  return c;
}

TEST(CommandResender, ReSendsTheLastTakeoffOncePerIntervalWithItsSeqAndAFreshUtime) {
  CommandResender resender(1'000'000);
  EXPECT_EQ(resender.due(5'000'000), nullptr) << "nothing sent yet";
  resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff, 1.5));
  EXPECT_EQ(resender.due(1'999'999), nullptr);
  const Command* resend = resender.due(2'000'000);
  ASSERT_NE(resend, nullptr);
  EXPECT_EQ(resend->seq, 1);
  EXPECT_EQ(resend->utime, 2'000'000);
  EXPECT_EQ(resend->command, CommandType::kTakeoff);
  EXPECT_EQ(resend->position[2], 1.5);
  EXPECT_EQ(resender.due(2'500'000), nullptr);
  // Ticks of the mission loop are late, not on the grid: the interval runs from the last re-send.
  ASSERT_NE(resender.due(3'020'000), nullptr);
  EXPECT_EQ(resender.due(4'000'000), nullptr);
  ASSERT_NE(resender.due(4'020'000), nullptr);
  EXPECT_EQ(resender.resends(), 3);
}

TEST(CommandResender, AGotoReplacesTheTakeoff) {
  CommandResender resender(1'000'000);
  resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff));
  resender.sent(sentAt(1'400'000, 2, CommandType::kGoto, 2.0));
  EXPECT_EQ(resender.due(2'000'000), nullptr) << "interval counts from the GOTO";
  const Command* resend = resender.due(2'400'000);
  ASSERT_NE(resend, nullptr);
  EXPECT_EQ(resend->seq, 2);
  EXPECT_EQ(resend->command, CommandType::kGoto);
  EXPECT_EQ(resend->position[2], 2.0);
}

TEST(CommandResender, EveryCommandTypeIsReSentUntilTheNextCommand) {
  // A LAND sent once and lost under 0.5 % loss never landed the vehicle (or left the recorder's
  // log without it); ARM and DISARM are re-sent alike.
  for (CommandType type : {CommandType::kArm, CommandType::kLand, CommandType::kDisarm}) {
    CommandResender resender(1'000'000);
    resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff));
    resender.sent(sentAt(1'500'000, 2, type));
    EXPECT_EQ(resender.due(2'000'000), nullptr) << "interval counts from the new command";
    const Command* resend = resender.due(2'500'000);
    ASSERT_NE(resend, nullptr) << "command type " << static_cast<int>(type);
    EXPECT_EQ(resend->seq, 2);
    EXPECT_EQ(resend->command, type);
    resender.sent(sentAt(2'700'000, 3, CommandType::kGoto, 2.0));
    resend = resender.due(3'700'000);
    ASSERT_NE(resend, nullptr);
    EXPECT_EQ(resend->seq, 3) << "the next command replaces it";
  }
}

TEST(CommandResender, ZeroIntervalNeverReSends) {
  CommandResender resender(0);
  resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff));
  for (int64_t t = 1'000'000; t < 10'000'000; t += 10'000) ASSERT_EQ(resender.due(t), nullptr);
}

}  // namespace
}  // namespace sdlqr::mission
