#include "sdlqr/health/validate.hpp"

#include <cmath>

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/in_flight.hpp"
#include "sdlqr/math/vehicle.hpp"

#include "validate_rows.hpp"

namespace sdlqr {

namespace {

template <class Derived>
bool finite(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite();
}

bool unitQuaternion(const Quat& q, const ValidationLimits& limits) {
  return std::abs(q.norm() - 1.0) <= limits.quaternion_norm_tolerance;
}

bool stateInRange(const State& x, const ValidationLimits& limits) {
  return position(x).cwiseAbs().maxCoeff() <= limits.max_position &&
         velocity(x).norm() <= limits.max_velocity;
}

// A model's thrust gain: produced over commanded thrust (the adaptive law bounds its estimate well inside).
bool thrustGainInRange(double gain) { return gain >= 0.1 && gain <= 10.0; }

bool modeKnown(ReferenceMode mode) {
  const auto v = static_cast<int8_t>(mode);
  return v >= 0 && v <= static_cast<int8_t>(ReferenceMode::kTransition);
}

}  // namespace

ValidationLimits::ValidationLimits() { declaration().setDefaults(*this); }

const ParamTable<ValidationLimits>& ValidationLimits::declaration() {
  static const ParamTable<ValidationLimits> table = validationLimitsRows();
  return table;
}

std::string lqrLimitsInvalidReason(const LqrParams& lqr, const ValidationLimits& limits) {
  if (!(lqr.omega_max <= limits.max_body_rate)) return "omega_max: must be <= validation.max_body_rate";
  if (!(lqr.c_max <= limits.max_thrust)) return "c_max: must be <= validation.max_thrust";
  return {};
}

RejectReason validate(const StateEstimate& m, const ValidationLimits& limits) {
  if (!finite(m.position) || !finite(m.orientation) || !finite(m.velocity) || !finite(m.body_rate) ||
      !finite(m.gyro_bias) || !finite(m.accel_bias) || !finite(m.position_std) || !finite(m.attitude_std)) {
    return RejectReason::kNonFinite;
  }
  const auto status = static_cast<int8_t>(m.status);
  if (status < 0 || status > 2) return RejectReason::kBadEnum;
  if (!unitQuaternion(m.orientation, limits)) return RejectReason::kQuaternionNorm;
  if (!stateInRange(m.state(), limits) || m.body_rate.norm() > limits.max_body_rate || m.utime < 0) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

RejectReason validate(const GainSet& m, const ValidationLimits& limits) {
  if (!finite(m.K) || !finite(m.x_lin) || !finite(m.u_lin) || !finite(m.q_diag) || !finite(m.r_diag) ||
      !std::isfinite(m.dt)) {
    return RejectReason::kNonFinite;
  }
  if (!finite(m.K_aug) || !std::isfinite(m.thrust_time_constant) || !std::isfinite(m.thrust_gain)) {
    return RejectReason::kNonFinite;
  }
  if (m.status != SolveStatus::kOk) return RejectReason::kBadStatus;
  const auto method = static_cast<int8_t>(m.method);
  if (method < 0 || method > 1 || !isControlLaw(m.law)) return RejectReason::kBadEnum;
  if (m.K_aug.cwiseAbs().maxCoeff() > limits.max_gain || m.thrust_time_constant < 0.0 || !thrustGainInRange(m.thrust_gain)) {
    return RejectReason::kOutOfRange;
  }
  if (!unitQuaternion(orientation(m.x_lin), limits)) return RejectReason::kQuaternionNorm;
  if (m.K.cwiseAbs().maxCoeff() > limits.max_gain || !(m.dt > 0.0 && m.dt <= 1.0) || m.utime < 0) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

RejectReason validate(const RateCommand& m, const ValidationLimits& limits) {
  if (!finite(m.body_rate) || !std::isfinite(m.thrust)) return RejectReason::kNonFinite;
  const auto status = static_cast<int8_t>(m.gains_status);
  if (status < 0 || status > 2 || !isControlLaw(m.law)) return RejectReason::kBadEnum;
  if (m.body_rate.norm() > limits.max_body_rate || m.thrust < 0.0 || m.thrust > limits.max_thrust || m.utime < 0) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

RejectReason validate(const Reference& m, const ValidationLimits& limits) {
  if (!finite(m.x) || !finite(m.u) || !std::isfinite(m.gamma) || !std::isfinite(m.thrust_gain)) {
    return RejectReason::kNonFinite;
  }
  if (!thrustGainInRange(m.thrust_gain)) return RejectReason::kOutOfRange;
  if (!modeKnown(m.mode)) return RejectReason::kBadEnum;
  if (!unitQuaternion(orientation(m.x), limits)) return RejectReason::kQuaternionNorm;
  if (!stateInRange(m.x, limits) || bodyRate(m.u).norm() > limits.max_body_rate || m.u[kThrust] < 0.0 ||
      m.u[kThrust] > limits.max_thrust) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

RejectReason validate(const Command& m, const ValidationLimits& limits) {
  if (!finite(m.position) || !std::isfinite(m.yaw)) return RejectReason::kNonFinite;
  const auto command = static_cast<int8_t>(m.command);
  if (command < static_cast<int8_t>(CommandType::kArm) || command > static_cast<int8_t>(CommandType::kLand)) {
    return RejectReason::kBadEnum;
  }
  if (m.position.cwiseAbs().maxCoeff() > limits.max_position || std::abs(m.yaw) > 100.0) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

// The values against their declarations (checkInFlight: groups, choices, finite, ranges, rules),
// then the message limits of the validation section. The vehicle's own check (liftable) is the
// bodyrate loop's.
RejectReason validate(const ParamsUpdate& m, const ValidationLimits& limits) {
  switch (checkInFlight(m).verdict) {
    case InFlightVerdict::kOk: break;
    case InFlightVerdict::kUnknownGroup:
    case InFlightVerdict::kBadChoice: return RejectReason::kBadEnum;
    case InFlightVerdict::kNonFinite: return RejectReason::kNonFinite;
    case InFlightVerdict::kOutOfRange: return RejectReason::kOutOfRange;
  }
  if ((m.field_mask & ParamsUpdate::kWeights) &&
      (m.q_diag.maxCoeff() > limits.max_weight || m.r_diag.maxCoeff() > limits.max_weight)) {
    return RejectReason::kOutOfRange;
  }
  if ((m.field_mask & ParamsUpdate::kLimits) && !(m.omega_max <= limits.max_body_rate && m.c_max <= limits.max_thrust)) {
    return RejectReason::kOutOfRange;
  }
  return RejectReason::kNone;
}

RejectReason validate(const Trajectory& m, const ValidationLimits& limits) {
  if (m.samples.size() < 2 || static_cast<int>(m.samples.size()) > limits.max_trajectory_samples) {
    return RejectReason::kBadSize;
  }
  if (m.tracking != ReferenceMode::kSpatial && m.tracking != ReferenceMode::kTemporal) return RejectReason::kBadEnum;
  double previous_t = -1e300;
  for (const TrajectorySample& s : m.samples) {
    if (!std::isfinite(s.t) || !finite(s.x) || !finite(s.u)) return RejectReason::kNonFinite;
    if (!unitQuaternion(orientation(s.x), limits)) return RejectReason::kQuaternionNorm;
    if (s.t <= previous_t || !stateInRange(s.x, limits) || s.u[kThrust] < 0.0 || s.u[kThrust] > limits.max_thrust ||
        bodyRate(s.u).norm() > limits.max_body_rate) {
      return RejectReason::kOutOfRange;
    }
    previous_t = s.t;
  }
  return RejectReason::kNone;
}

RejectReason ClockGate::offer(int64_t utime) {
  if (last_utime_ >= 0 && utime <= last_utime_) return RejectReason::kTimeBackwards;
  if (last_utime_ < 0 || utime - last_utime_ <= max_jump_us_) {
    last_utime_ = utime;
    candidate_count_ = 0;
    return RejectReason::kNone;
  }
  const bool continues_candidate =
      candidate_count_ > 0 && utime > candidate_utime_ && utime - candidate_utime_ <= max_jump_us_;
  candidate_count_ = continues_candidate ? candidate_count_ + 1 : 1;
  candidate_utime_ = utime;
  if (candidate_count_ < confirmations_) return RejectReason::kTimeFuture;
  last_utime_ = utime;
  candidate_count_ = 0;
  return RejectReason::kNone;
}

}  // namespace sdlqr
