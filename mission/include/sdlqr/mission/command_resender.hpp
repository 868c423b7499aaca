#pragma once
// Re-sends the mission's current command (the last ARM, TAKEOFF, GOTO, LAND or DISARM) at a fixed
// interval of simulation time, with its own seq and a fresh utime, until the next command: a
// controller restarted mid-flight learns the setpoint from it, a lost datagram of a command sent
// once (under loss a LAND missed by the controller never lands, missed by the recorder is a
// flight the analyzer cannot judge) arrives a second later, and every running subscriber
// recognises the seq it has handled already (the same instance never acts on a command twice).
// The first re-send comes a tenth of the interval after the command: a command replaced sooner than
// the interval (the scenario's ARM, half a second before its TAKEOFF) is otherwise sent only once,
// and its datagram lost under 0.5 % loss left the recorder's log without it (loss_hover_jumps failed
// `event_in_log[arm]` on 2026-12-05).

#include <cstdint>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr::mission {

class CommandResender {
 public:
  // interval_utime <= 0: never re-send.
  explicit CommandResender(int64_t interval_utime) : interval_utime_(interval_utime) {}

  // Every COMMAND as published (stamped with its utime and seq).
  void sent(const Command& command) {
    current_ = command;
    active_ = interval_utime_ > 0;
    last_utime_ = command.utime;
    wait_utime_ = interval_utime_ / 10;
  }

  // The re-send due at `now_utime` (current command restamped with now), or nullptr.
  const Command* due(int64_t now_utime) {
    if (!active_ || now_utime - last_utime_ < wait_utime_) return nullptr;
    last_utime_ = now_utime;
    wait_utime_ = interval_utime_;
    current_.utime = now_utime;
    ++resends_;
    return &current_;
  }

  int64_t resends() const { return resends_; }

 private:
  int64_t interval_utime_;
  Command current_;
  bool active_ = false;
  int64_t last_utime_ = 0;
  int64_t wait_utime_ = 0;  // from last_utime_ to the next re-send
  int64_t resends_ = 0;
};

}  // namespace sdlqr::mission
