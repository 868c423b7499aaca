#include "sdlqr/px4/command_sender.hpp"

#include <algorithm>

#include "command_sender_rows.hpp"

namespace sdlqr::px4 {

CommandRetry::CommandRetry() { declaration().setDefaults(*this); }

const ParamTable<CommandRetry>& CommandRetry::declaration() {
  static const ParamTable<CommandRetry> table = commandRetryRows();
  return table;
}

const char* outcomeName(CommandOutcome outcome) {
  switch (outcome) {
    case CommandOutcome::kAccepted: return "accepted";
    case CommandOutcome::kRefused: return "refused";
    case CommandOutcome::kTimedOut: return "timed_out";
  }
  return "unknown";
}

bool CommandSender::send(const mavlink::CommandLong& command, double now_s, mavlink::MessageSink& link) {
  if (queued_ == queue_.size()) return false;
  queue_[queued_++] = command;
  if (!in_flight_) startNext(now_s, link);
  return true;
}

void CommandSender::startNext(double now_s, mavlink::MessageSink& link) {
  in_flight_.reset();
  if (queued_ == 0) return;
  in_flight_ = queue_[0];
  std::move(queue_.begin() + 1, queue_.begin() + static_cast<std::ptrdiff_t>(queued_), queue_.begin());
  --queued_;
  attempts_ = 0;
  in_progress_ = false;
  first_send_s_ = now_s;
  transmit(now_s, link);
}

void CommandSender::transmit(double now_s, mavlink::MessageSink& link) {
  in_flight_->confirmation = static_cast<uint8_t>(std::min(attempts_, 255));
  link.send(*in_flight_);
  ++attempts_;
  last_send_s_ = now_s;
}

std::optional<CommandResult> CommandSender::onAck(const mavlink::CommandAck& ack, double now_s,
                                                  mavlink::MessageSink& link) {
  if (!in_flight_ || ack.command != in_flight_->command) return std::nullopt;
  if (ack.result == mavlink::mav_result::kInProgress) {
    in_progress_ = true;
    return std::nullopt;
  }
  CommandResult result;
  result.command = in_flight_->command;
  result.param1 = in_flight_->param1;
  result.outcome = ack.result == mavlink::mav_result::kAccepted ? CommandOutcome::kAccepted : CommandOutcome::kRefused;
  result.result = ack.result;
  result.attempts = attempts_;
  result.seconds = now_s - first_send_s_;
  startNext(now_s, link);
  return result;
}

std::optional<CommandResult> CommandSender::onTime(double now_s, mavlink::MessageSink& link) {
  if (!in_flight_ || now_s - last_send_s_ < retry_.interval_s) return std::nullopt;
  if (in_progress_) {
    // Working on it: wait a whole budget of attempts for its final answer, sending nothing.
    if (now_s - first_send_s_ < retry_.interval_s * retry_.attempts * 2) return std::nullopt;
  } else if (attempts_ < retry_.attempts) {
    transmit(now_s, link);
    return std::nullopt;
  }
  CommandResult result;
  result.command = in_flight_->command;
  result.param1 = in_flight_->param1;
  result.outcome = CommandOutcome::kTimedOut;
  result.attempts = attempts_;
  result.seconds = now_s - first_send_s_;
  startNext(now_s, link);
  return result;
}

bool CommandSender::pending(uint16_t command) const {
  if (in_flight_ && in_flight_->command == command) return true;
  return std::any_of(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(queued_),
                     [command](const mavlink::CommandLong& c) { return c.command == command; });
}

void CommandSender::clear() {
  in_flight_.reset();
  queued_ = 0;
}

}  // namespace sdlqr::px4
