#pragma once
// MAVLink commands to the autopilot as PX4's offboard examples and mavros send them: one command
// in flight at a time, sent again every `interval_s` (confirmation counting up) until its
// COMMAND_ACK or `attempts` sends have gone unanswered (timed out). Later commands wait in a
// short queue. An ACK with result IN_PROGRESS keeps the command waiting without resending; any
// other result finishes it (ACCEPTED, or refused with that result). Pure and clock-free: the
// caller passes the time [s] and the link.

#include <array>
#include <cstdint>
#include <optional>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/mavlink/messages.hpp"

namespace sdlqr::px4 {

struct CommandRetry {
  double interval_s;  // [s] between sends of an unanswered command
  int attempts;       // [-] sends before it times out

  CommandRetry();
  static const ParamTable<CommandRetry>& declaration();
};

enum class CommandOutcome : uint8_t { kAccepted, kRefused, kTimedOut };

struct CommandResult {
  uint16_t command = 0;     // MAV_CMD
  float param1 = 0.0f;      // the command's first parameter (SET_MESSAGE_INTERVAL: the message id)
  CommandOutcome outcome = CommandOutcome::kTimedOut;
  uint8_t result = 0;       // MAV_RESULT of the ACK (kRefused)
  int attempts = 0;         // sends
  double seconds = 0.0;     // [s] from the first send to the answer or the time-out
};

const char* outcomeName(CommandOutcome outcome);  // "accepted", "refused", "timed_out"

class CommandSender {
 public:
  explicit CommandSender(const CommandRetry& retry) : retry_(retry) {}

  // Queues `command` (sent now when nothing is in flight). False when the queue is full.
  bool send(const mavlink::CommandLong& command, double now_s, mavlink::MessageSink& link);
  // An ACK from the autopilot; one for no command in flight is ignored (counted by the caller).
  // Returns the finished command's result, if this ACK finished one.
  std::optional<CommandResult> onAck(const mavlink::CommandAck& ack, double now_s, mavlink::MessageSink& link);
  // Resends when due. Returns the result of a command that timed out now.
  std::optional<CommandResult> onTime(double now_s, mavlink::MessageSink& link);

  bool pending(uint16_t command) const;  // in flight or queued
  bool idle() const { return !in_flight_ && queued_ == 0; }
  // Forgets every queued and in-flight command (the link was lost: the autopilot's answer, if any,
  // is gone; the caller decides again what to ask).
  void clear();

 private:
  void startNext(double now_s, mavlink::MessageSink& link);
  void transmit(double now_s, mavlink::MessageSink& link);

  CommandRetry retry_;
  std::optional<mavlink::CommandLong> in_flight_;
  int attempts_ = 0;
  double first_send_s_ = 0.0, last_send_s_ = 0.0;
  bool in_progress_ = false;
  std::array<mavlink::CommandLong, 8> queue_{};
  size_t queued_ = 0;
};

}  // namespace sdlqr::px4
