#include "sdlqr/lowlevel/rate_control.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/lowlevel/low_pass.hpp"

#include "rate_control_rows.hpp"

namespace sdlqr::lowlevel {

RateControlParams::RateControlParams() { declaration().setDefaults(*this); }

const ParamTable<RateControlParams>& RateControlParams::declaration() {
  static const ParamTable<RateControlParams> table = rateControlParamsRows();
  return table;
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
