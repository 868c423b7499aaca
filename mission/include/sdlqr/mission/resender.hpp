#pragma once
// Re-sends the mission's current message of a channel at a fixed interval of simulation time, with
// its own seq and a fresh utime, until the next one: the current command (the last ARM, TAKEOFF,
// GOTO, LAND or DISARM) and the current pull (DISTURBANCE). A controller restarted mid-flight
// learns the setpoint from it, a lost datagram of a message sent once (under loss a LAND missed by
// the controller never lands, missed by the recorder is a flight the analyzer cannot judge) arrives
// later, and every running subscriber recognises the seq it has handled already (the same instance
// never acts on a message twice). The first re-send comes a tenth of the interval after the
// message: a command replaced sooner than the interval (the scenario's ARM, half a second before
// its TAKEOFF) is otherwise sent only once, and its datagram lost under 0.5 % loss left the
// recorder's log without it (loss_hover_jumps failed `event_in_log[arm]` on 2026-12-05).

#include <cstdint>

#include "sdlqr/messages/messages.hpp"

namespace sdlqr::mission {

template <class Message>
class Resender {
 public:
  // interval_utime <= 0: never re-send.
  explicit Resender(int64_t interval_utime) : interval_utime_(interval_utime) {}

  // Every message of the channel as published (stamped with its utime and seq).
  void sent(const Message& message) {
    current_ = message;
    active_ = interval_utime_ > 0;
    last_utime_ = message.utime;
    wait_utime_ = interval_utime_ / 10;
  }

  // The re-send due at `now_utime` (current message restamped with now), or nullptr.
  const Message* due(int64_t now_utime) {
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
  Message current_;
  bool active_ = false;
  int64_t last_utime_ = 0;
  int64_t wait_utime_ = 0;  // from last_utime_ to the next re-send
  int64_t resends_ = 0;
};

using CommandResender = Resender<Command>;
using DisturbanceResender = Resender<Disturbance>;

}  // namespace sdlqr::mission
