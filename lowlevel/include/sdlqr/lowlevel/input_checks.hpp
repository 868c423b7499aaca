#pragma once
// Validation of what arrives from the bus before it can reach the loop: a rejected message is
// counted under its reason and otherwise ignored.

#include <cstdint>
#include <limits>
#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::lowlevel {

inline constexpr int64_t kNoTime = std::numeric_limits<int64_t>::min();

// Declared (key, unit, default, range, help) in lowlevel/params/input_checks.yaml.
// The RATE_CMD body-rate bound is the stack's one, ValidationLimits::max_body_rate.
struct InputLimits : DeclaredParams<InputLimits> {
  double max_command_lead;
  double max_gyro;
  double max_accel;
  double max_imu_gap;

  InputLimits();
  static const ParamTable<InputLimits>& declaration();
};

// kNonFinite, kOutOfRange (beyond the sensor range), kTimeBackwards (not newer than the previous
// accepted sample), kTimeGap (more than max_imu_gap after it).
// last_utime: utime of the previous accepted sample, kNoTime for none.
RejectReason checkImu(const ImuSample& sample, const InputLimits& limits, int64_t last_utime);

// kNonFinite, kOutOfRange (|omega| above max_body_rate, thrust outside [0, max_thrust]),
// kTimeBackwards (older than the last accepted command), kNoClock (no IMU sample yet),
// kTimeFuture (further ahead of the IMU clock than max_command_lead), kStale (older than the
// RATE_CMD timeout at arrival).
// max_body_rate [rad/s]: bound on |omega| (ValidationLimits::max_body_rate); max_thrust [m/s^2];
// imu_utime: latest accepted IMU time (kNoTime: none yet); last_utime: utime of the last accepted
// command (kNoTime: none); max_age [s]: the RATE_CMD timeout.
RejectReason checkRateCommand(const RateCommand& command, const InputLimits& limits, double max_body_rate,
                              double max_thrust, int64_t imu_utime, int64_t last_utime, double max_age);

}  // namespace sdlqr::lowlevel
