#include "sdlqr/lowlevel/input_checks.hpp"

#include <cmath>

#include "input_checks_rows.hpp"


namespace sdlqr::lowlevel {

InputLimits::InputLimits() { declaration().setDefaults(*this); }

const ParamTable<InputLimits>& InputLimits::declaration() {
  static const ParamTable<InputLimits> table = inputLimitsRows();
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
