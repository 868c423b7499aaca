// The mission's re-send of its current setpoint command (for a controller restarted mid-flight, and
// a lost datagram) and of its current pull.

#include <gtest/gtest.h>

#include "sdlqr/mission/resender.hpp"

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

TEST(CommandResender, ReSendsTheLastTakeoffATenthOfTheIntervalLaterThenOncePerIntervalWithItsSeqAndAFreshUtime) {
  CommandResender resender(1'000'000);
  EXPECT_EQ(resender.due(5'000'000), nullptr) << "nothing sent yet";
  resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff, 1.5));
  EXPECT_EQ(resender.due(1'099'999), nullptr);
  const Command* resend = resender.due(1'100'000);
  ASSERT_NE(resend, nullptr);
  EXPECT_EQ(resend->seq, 1);
  EXPECT_EQ(resend->utime, 1'100'000);
  EXPECT_EQ(resend->command, CommandType::kTakeoff);
  EXPECT_EQ(resend->position[2], 1.5);
  EXPECT_EQ(resender.due(2'099'999), nullptr) << "then a whole interval";
  ASSERT_NE(resender.due(2'100'000), nullptr);
  // Ticks of the mission loop are late, not on the grid: the interval runs from the last re-send.
  ASSERT_NE(resender.due(3'120'000), nullptr);
  EXPECT_EQ(resender.due(4'100'000), nullptr);
  ASSERT_NE(resender.due(4'120'000), nullptr);
  EXPECT_EQ(resender.resends(), 4);
}

TEST(CommandResender, AnArmReplacedHalfAnIntervalLaterIsReSentBeforeIt) {
  // hover_jumps: ARM at 0.5 s, TAKEOFF at 1.0 s. Re-sent only once per interval, the ARM was sent
  // once, and its datagram lost under loss left the log without the scenario's arm.
  CommandResender resender(1'000'000);
  resender.sent(sentAt(500'000, 1, CommandType::kArm));
  EXPECT_EQ(resender.due(590'000), nullptr);
  const Command* resend = resender.due(600'000);
  ASSERT_NE(resend, nullptr);
  EXPECT_EQ(resend->seq, 1);
  EXPECT_EQ(resend->command, CommandType::kArm);
  resender.sent(sentAt(1'000'000, 2, CommandType::kTakeoff));
  resend = resender.due(1'100'000);
  ASSERT_NE(resend, nullptr) << "the TAKEOFF's own early re-send";
  EXPECT_EQ(resend->seq, 2);
}

TEST(CommandResender, AGotoReplacesTheTakeoff) {
  CommandResender resender(1'000'000);
  resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff));
  resender.sent(sentAt(1'040'000, 2, CommandType::kGoto, 2.0));
  EXPECT_EQ(resender.due(1'100'000), nullptr) << "the wait counts from the GOTO";
  const Command* resend = resender.due(1'140'000);
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
    EXPECT_EQ(resender.due(1'599'999), nullptr) << "the wait counts from the new command";
    const Command* resend = resender.due(1'600'000);
    ASSERT_NE(resend, nullptr) << "command type " << static_cast<int>(type);
    EXPECT_EQ(resend->seq, 2);
    EXPECT_EQ(resend->command, type);
    resender.sent(sentAt(2'700'000, 3, CommandType::kGoto, 2.0));
    resend = resender.due(2'800'000);
    ASSERT_NE(resend, nullptr);
    EXPECT_EQ(resend->seq, 3) << "the next command replaces it";
  }
}

TEST(CommandResender, ZeroIntervalNeverReSends) {
  CommandResender resender(0);
  resender.sent(sentAt(1'000'000, 1, CommandType::kTakeoff));
  for (int64_t t = 1'000'000; t < 10'000'000; t += 10'000) ASSERT_EQ(resender.due(t), nullptr);
}

TEST(DisturbanceResender, ReSendsThePullWithItsSeqAndStartAndAFreshUtime) {
  // A pull sent once and lost under loss never happened: the simulator applies a seq once.
  DisturbanceResender resender(1'000'000);
  Disturbance pull;
  pull.seq = 4;
  pull.utime = 39'000'000;
  pull.start_utime = 39'000'000;
  pull.duration = 2.0;
  resender.sent(pull);
  EXPECT_EQ(resender.due(39'099'999), nullptr);
  const Disturbance* resend = resender.due(39'100'000);
  ASSERT_NE(resend, nullptr);
  EXPECT_EQ(resend->seq, 4);
  EXPECT_EQ(resend->utime, 39'100'000);
  EXPECT_EQ(resend->start_utime, 39'000'000) << "the same pull, not a later one";
  EXPECT_EQ(resend->duration, 2.0);
}

}  // namespace
}  // namespace sdlqr::mission
