#include "sdlqr/lowlevel/rate_control.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/lowlevel/low_pass.hpp"

namespace sdlqr::lowlevel {

RateControlParams::RateControlParams() { declaration().setDefaults(*this); }

const ParamTable<RateControlParams>& RateControlParams::declaration() {
  static const ParamTable<RateControlParams> table = [] {
    using P = RateControlParams;
    ParamTable<P> t("body-rate PID per axis (roll, pitch, yaw)");
    // Tuned on a rigid body with the default inertia and a 30 ms motor lag: a 1 rad/s roll or
    // pitch step settles to 2 % in about 65 ms with < 1 % overshoot (tests/unit/lowlevel).
    // Yaw is slower on purpose: rotor drag gives it a tenth of the roll authority.
    t.list("p", &P::p, {120.0, 120.0, 12.0}, "1/s", Range::above(0.0), "rad/s^2 per rad/s of rate error (roll, pitch, yaw)");
    t.list("i", &P::i, {30.0, 30.0, 1.0}, "1/s^2", Range::atLeast(0.0), "rad/s^2 per rad of integrated rate error");
    t.list("d", &P::d, {2.0, 2.0, 0.0}, "-", Range::atLeast(0.0), "rad/s^2 per rad/s^2 of measured rate change");
    t.list("integral_limit", &P::integral_limit, {30.0, 30.0, 10.0}, "rad/s^2", Range::atLeast(0.0),
           "bound of the integral term");
    // Above a few hundred hertz the filter would pass the 1 kHz sampling noise untouched.
    t.number("d_cutoff_hz", &P::d_cutoff_hz, 40.0, "Hz", Range::openClosed(0.0, 400.0), "low-pass on the gyro derivative");
    t.flag("gyroscopic_feedforward", &P::gyroscopic_feedforward, true, "add omega x J omega to the torque");
    return t;
  }();
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
