#include "sdlqr/lowlevel/input_checks.hpp"

#include <cmath>


namespace sdlqr::lowlevel {

InputLimits::InputLimits() { declaration().setDefaults(*this); }

const ParamTable<InputLimits>& InputLimits::declaration() {
  static const ParamTable<InputLimits> table = [] {
    using P = InputLimits;
    ParamTable<P> t("checks of what arrives from the bus (RATE_CMD |omega|: validation.max_body_rate)");
    t.number("max_command_lead", &P::max_command_lead, 0.1, "s", Range::closed(0.0, 10.0),
             "RATE_CMD utime allowed ahead of IMU time");
    t.number("max_gyro", &P::max_gyro, 35.0, "rad/s", Range::openClosed(0.0, 1000.0),
             "IMU range per axis: beyond a 2000 deg/s gyro's range");
    t.number("max_accel", &P::max_accel, 160.0, "m/s^2", Range::openClosed(10.0, 10000.0),
             "IMU range per axis: beyond a 16 g accelerometer's range");
    t.number("max_imu_gap", &P::max_imu_gap, 1.0, "s", Range::openClosed(0.0, 60.0),
             "larger forward jumps of IMU time are rejected");
    return t;
  }();
  return table;
}

RejectReason checkImu(const ImuSample& sample, const InputLimits& limits, int64_t last_utime) {
  if (!sample.gyro.allFinite() || !sample.accel.allFinite()) return RejectReason::kNonFinite;
  if (sample.gyro.cwiseAbs().maxCoeff() > limits.max_gyro || sample.accel.cwiseAbs().maxCoeff() > limits.max_accel) {
    return RejectReason::kOutOfRange;
  }
  if (last_utime != kNoTime) {
    if (sample.utime <= last_utime) return RejectReason::kTimeBackwards;
    if (1e-6 * (static_cast<double>(sample.utime) - static_cast<double>(last_utime)) > limits.max_imu_gap) {
      return RejectReason::kTimeGap;
    }
  }
  return RejectReason::kNone;
}

RejectReason checkRateCommand(const RateCommand& command, const InputLimits& limits, double max_body_rate,
                              double max_thrust, int64_t imu_utime, int64_t last_utime, double max_age) {
  if (!command.body_rate.allFinite() || !std::isfinite(command.thrust)) return RejectReason::kNonFinite;
  if (command.body_rate.norm() > max_body_rate) return RejectReason::kOutOfRange;
  if (!(command.thrust >= 0.0 && command.thrust <= max_thrust)) return RejectReason::kOutOfRange;
  // Equal times are fine: two commands may come from the same state estimate.
  if (last_utime != kNoTime && command.utime < last_utime) return RejectReason::kTimeBackwards;
  if (imu_utime == kNoTime) return RejectReason::kNoClock;
  // In double: a hostile utime must not overflow the subtraction.
  const double lead = 1e-6 * (static_cast<double>(command.utime) - static_cast<double>(imu_utime));
  if (lead > limits.max_command_lead) return RejectReason::kTimeFuture;
  if (-lead > max_age) return RejectReason::kStale;
  return RejectReason::kNone;
}

}  // namespace sdlqr::lowlevel
