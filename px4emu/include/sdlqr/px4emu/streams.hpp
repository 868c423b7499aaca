#pragma once
// The MAVLink streams of PX4's onboard link (PX4 mavlink_main.cpp, mode onboard: ODOMETRY 30 Hz,
// HIGHRES_IMU 50, ATTITUDE_QUATERNION 50, LOCAL_POSITION_NED 30, EXTENDED_SYS_STATE 5, HEARTBEAT 1;
// the others PX4 streams have no definition here) and MAV_CMD_SET_MESSAGE_INTERVAL: an interval
// [us] > 0 sets the rate, 0 restores the default, -1 stops the stream. Each stream keeps its
// schedule on the emulated PX4's clock: no burst after a late step. Pure.

#include <array>
#include <cstdint>

namespace sdlqr::px4emu {

class Streams {
 public:
  Streams();
  // The MAV_RESULT: ACCEPTED, or DENIED for a message this emulator does not stream.
  uint8_t setInterval(uint32_t message_id, float interval_us);
  // True when the stream is due at `now_us`; sent() then schedules its next one.
  bool due(uint32_t message_id, int64_t now_us) const;
  void sent(uint32_t message_id, int64_t now_us);
  double rateHz(uint32_t message_id) const;  // 0: stopped or unknown

 private:
  struct Stream {
    uint32_t id;
    int64_t default_interval_us;
    int64_t interval_us;  // -1: stopped
    int64_t next_us = 0;
  };
  Stream* find(uint32_t message_id);
  const Stream* find(uint32_t message_id) const;
  std::array<Stream, 6> streams_;
};

}  // namespace sdlqr::px4emu
