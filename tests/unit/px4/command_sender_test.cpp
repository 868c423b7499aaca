// The command sender (px4/command_sender.hpp): one command in flight, resent with a rising
// confirmation until its ACK, a time-out after the last attempt, IN_PROGRESS waits, a queue behind.

#include <gtest/gtest.h>

#include <vector>

#include "sdlqr/px4/command_sender.hpp"

namespace sdlqr::px4 {
namespace {

struct Kept {
  std::vector<mavlink::CommandLong> commands;
  void operator()(const mavlink::CommandLong& c) { commands.push_back(c); }
  template <class M>
  void operator()(const M&) {}
};

mavlink::CommandLong commandOf(uint16_t id) {
  mavlink::CommandLong c;
  c.command = id;
  return c;
}

mavlink::CommandAck ackOf(uint16_t id, uint8_t result) {
  mavlink::CommandAck a;
  a.command = id;
  a.result = result;
  return a;
}

// A sender with the default retry and the link it writes to, which keeps what was sent.
class CommandSenderTest : public ::testing::Test {
 protected:
  Kept kept;
  mavlink::MessageSinkTo<Kept&> link{kept};
  CommandSender sender{CommandRetry{}};
};

TEST_F(CommandSenderTest, ResendsWithRisingConfirmationThenTimesOut) {
  sender.send(commandOf(176), 0.0, link);
  std::optional<CommandResult> result;
  for (int i = 1; i <= 300 && !result; ++i) result = sender.onTime(0.01 * i, link);
  ASSERT_EQ(kept.commands.size(), 8u);
  for (size_t i = 0; i < kept.commands.size(); ++i) EXPECT_EQ(kept.commands[i].confirmation, i);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->outcome, CommandOutcome::kTimedOut);
  EXPECT_EQ(result->attempts, 8);
  EXPECT_NEAR(result->seconds, 8 * 0.25, 0.011);
  EXPECT_TRUE(sender.idle());
}

TEST_F(CommandSenderTest, AnAckFinishesItAndTheNextQueuedGoesOut) {
  sender.send(commandOf(511), 0.0, link);
  sender.send(commandOf(176), 0.0, link);
  EXPECT_EQ(kept.commands.size(), 1u);
  EXPECT_TRUE(sender.pending(176));
  EXPECT_FALSE(sender.onAck(ackOf(176, 0), 0.1, link));  // not the one in flight
  const auto result = sender.onAck(ackOf(511, mavlink::mav_result::kDenied), 0.1, link);
  ASSERT_TRUE(result);
  EXPECT_EQ(result->outcome, CommandOutcome::kRefused);
  EXPECT_EQ(result->result, mavlink::mav_result::kDenied);
  ASSERT_EQ(kept.commands.size(), 2u);
  EXPECT_EQ(kept.commands[1].command, 176);
  EXPECT_EQ(sender.onAck(ackOf(176, 0), 0.2, link)->outcome, CommandOutcome::kAccepted);
  EXPECT_TRUE(sender.idle());
}

TEST_F(CommandSenderTest, InProgressWaitsWithoutResending) {
  sender.send(commandOf(400), 0.0, link);
  EXPECT_FALSE(sender.onAck(ackOf(400, mavlink::mav_result::kInProgress), 0.05, link));
  for (int i = 1; i < 300; ++i) EXPECT_FALSE(sender.onTime(0.01 * i, link));
  EXPECT_EQ(kept.commands.size(), 1u);
  EXPECT_EQ(sender.onAck(ackOf(400, 0), 3.0, link)->outcome, CommandOutcome::kAccepted);
}

}  // namespace
}  // namespace sdlqr::px4
