#include "sdlqr/lowlevel/rate_control.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "sdlqr/lowlevel/low_pass.hpp"
#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::lowlevel {

RateControlParams RateControlParams::load(const ConfigReader& reader) {
  reader.allowOnly({"p", "i", "d", "integral_limit", "d_cutoff_hz", "gyroscopic_feedforward"});
  RateControlParams params;
  reader.read("p", params.p);
  reader.read("i", params.i);
  reader.read("d", params.d);
  reader.read("integral_limit", params.integral_limit);
  reader.read("d_cutoff_hz", params.d_cutoff_hz);
  reader.read("gyroscopic_feedforward", params.gyroscopic_feedforward);
  throwIfInvalid(reader, params.invalidReason());
  return params;
}

std::string RateControlParams::invalidReason() const {
  auto axisReason = [](const char* key, int axis, const char* rule) {
    std::ostringstream why;
    why << key << "[" << axis << "]: " << rule;
    return why.str();
  };
  for (int axis = 0; axis < 3; ++axis) {
    if (!(std::isfinite(p[axis]) && p[axis] > 0.0)) return axisReason("p", axis, "must be finite and > 0");
    if (!(std::isfinite(i[axis]) && i[axis] >= 0.0)) return axisReason("i", axis, "must be finite and >= 0");
    if (!(std::isfinite(d[axis]) && d[axis] >= 0.0)) return axisReason("d", axis, "must be finite and >= 0");
    if (!(std::isfinite(integral_limit[axis]) && integral_limit[axis] >= 0.0)) {
      return axisReason("integral_limit", axis, "must be finite and >= 0");
    }
  }
  // Above a few hundred hertz the filter would pass the 1 kHz sampling noise untouched.
  if (!(d_cutoff_hz > 0.0 && d_cutoff_hz <= 400.0)) return "d_cutoff_hz: must be in (0, 400] Hz";
  return {};
}

RateController::RateController(const RateControlParams& params) : params_(params) {}

void RateController::setSaturation(const AxisFlags& positive, const AxisFlags& negative) {
  saturated_positive_ = positive;
  saturated_negative_ = negative;
}

void RateController::reset() {
  integral_.setZero();
  rate_derivative_.setZero();
  has_previous_rate_ = false;
  saturated_positive_.setConstant(false);
  saturated_negative_.setConstant(false);
  status_ = Status();
}

Vec3 RateController::update(const Vec3& rate, const Vec3& rate_sp, double dt, bool landed) {
  // Differentiating the measurement, not the error, keeps setpoint steps out of the D term.
  if (has_previous_rate_) {
    const Vec3 raw_derivative = (rate - previous_rate_) / dt;
    rate_derivative_ += lowPassAlpha(params_.d_cutoff_hz, dt) * (raw_derivative - rate_derivative_);
  }
  previous_rate_ = rate;
  has_previous_rate_ = true;

  const Vec3 error = rate_sp - rate;
  if (landed) {
    integral_.setZero();
  } else {
    for (int axis = 0; axis < 3; ++axis) {
      const double increment = params_.i[axis] * error[axis] * dt;
      // Growing into a saturated direction would only wind up; unwinding is always allowed.
      if ((increment > 0.0 && saturated_positive_[axis]) || (increment < 0.0 && saturated_negative_[axis])) continue;
      integral_[axis] = std::clamp(integral_[axis] + increment, -params_.integral_limit[axis], params_.integral_limit[axis]);
    }
  }

  status_.proportional = params_.p.cwiseProduct(error);
  status_.integral = integral_;
  status_.derivative = -params_.d.cwiseProduct(rate_derivative_);
  status_.rate_derivative = rate_derivative_;
  return status_.proportional + status_.integral + status_.derivative;
}

}  // namespace sdlqr::lowlevel
