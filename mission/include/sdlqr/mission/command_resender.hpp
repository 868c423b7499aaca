#pragma once
// Re-sends the mission's current setpoint command (the last TAKEOFF or GOTO) at a fixed interval
// of simulation time, with its own seq and a fresh utime: a controller restarted mid-flight learns
// the setpoint from it, and every running subscriber recognises the seq it has handled already.
// LAND, DISARM and ARM end the re-sending: they are no setpoint to return to.

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
    active_ = interval_utime_ > 0 &&
              (command.command == CommandType::kTakeoff || command.command == CommandType::kGoto);
    last_utime_ = command.utime;
  }

  // The re-send due at `now_utime` (current command restamped with now), or nullptr.
  const Command* due(int64_t now_utime) {
    if (!active_ || now_utime - last_utime_ < interval_utime_) return nullptr;
    last_utime_ = now_utime;
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
  int64_t resends_ = 0;
};

}  // namespace sdlqr::mission
