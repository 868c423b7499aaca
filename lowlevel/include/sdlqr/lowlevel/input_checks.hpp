#pragma once
// Validation of what arrives from the bus before it can reach the loop: a rejected message is
// counted under its reason and otherwise ignored.

#include <cstdint>
#include <limits>
#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::lowlevel {

inline constexpr int64_t kNoTime = std::numeric_limits<int64_t>::min();

struct InputLimits {
  double max_body_rate = 20.0;     // [rad/s] per axis: beyond this RATE_CMD is not physical
  double max_command_lead = 0.1;   // [s] RATE_CMD utime allowed ahead of the latest IMU time
  double max_gyro = 35.0;          // [rad/s] per axis: beyond a 2000 deg/s gyro's range
  double max_accel = 160.0;        // [m/s^2] per axis: beyond a 16 g accelerometer's range
  double max_imu_gap = 1.0;        // [s] a sample further ahead than this is a broken clock

  static InputLimits load(const ConfigReader& reader);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

// kNonFinite, kOutOfRange (beyond the sensor range), kTimeBackwards (not newer than the previous
// accepted sample), kTimeGap (more than max_imu_gap after it).
// last_utime: utime of the previous accepted sample, kNoTime for none.
RejectReason checkImu(const ImuSample& sample, const InputLimits& limits, int64_t last_utime);

// kNonFinite, kOutOfRange (|omega| above max_body_rate, thrust outside [0, max_thrust]),
// kTimeBackwards (older than the last accepted command), kNoClock (no IMU sample yet),
// kTimeFuture (further ahead of the IMU clock than max_command_lead), kStale (older than the
// RATE_CMD timeout at arrival).
// max_thrust [m/s^2]; imu_utime: latest accepted IMU time (kNoTime: none yet); last_utime: utime
// of the last accepted command (kNoTime: none); max_age [s]: the RATE_CMD timeout.
RejectReason checkRateCommand(const RateCommand& command, const InputLimits& limits, double max_thrust,
                                   int64_t imu_utime, int64_t last_utime, double max_age);

}  // namespace sdlqr::lowlevel
