#include "sdlqr/lowlevel/input_checks.hpp"

#include <cmath>

#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::lowlevel {

InputLimits InputLimits::load(const ConfigReader& reader) {
  reader.allowOnly({"max_body_rate", "max_command_lead", "max_gyro", "max_accel", "max_imu_gap"});
  InputLimits limits;
  reader.read("max_body_rate", limits.max_body_rate);
  reader.read("max_command_lead", limits.max_command_lead);
  reader.read("max_gyro", limits.max_gyro);
  reader.read("max_accel", limits.max_accel);
  reader.read("max_imu_gap", limits.max_imu_gap);
  throwIfInvalid(reader, limits.invalidReason());
  return limits;
}

std::string InputLimits::invalidReason() const {
  if (!(max_body_rate > 0.0 && max_body_rate <= 100.0)) return "max_body_rate: must be in (0, 100] rad/s";
  if (!(max_command_lead >= 0.0 && max_command_lead <= 10.0)) return "max_command_lead: must be in [0, 10] s";
  if (!(max_gyro > 0.0 && max_gyro <= 1000.0)) return "max_gyro: must be in (0, 1000] rad/s";
  if (!(max_accel > 10.0 && max_accel <= 10000.0)) return "max_accel: must be in (10, 10000] m/s^2";
  if (!(max_imu_gap > 0.0 && max_imu_gap <= 60.0)) return "max_imu_gap: must be in (0, 60] s";
  return {};
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

RejectReason checkRateCommand(const RateCommand& command, const InputLimits& limits, double max_thrust,
                                   int64_t imu_utime, int64_t last_utime, double max_age) {
  if (!command.body_rate.allFinite() || !std::isfinite(command.thrust)) return RejectReason::kNonFinite;
  if (command.body_rate.cwiseAbs().maxCoeff() > limits.max_body_rate) return RejectReason::kOutOfRange;
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
