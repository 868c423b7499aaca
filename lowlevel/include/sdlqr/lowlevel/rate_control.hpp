#pragma once
// Body-rate PID, per axis, producing the angular acceleration the mixer should realize.
// Derivative on the measurement (a setpoint step gives no derivative kick) through a first-order
// low-pass; integral clamped and frozen in the direction the mixer reports as saturated; the
// integral is reset while landed, where it would only learn the contact torque of the ground.
// Plain C++ with no clock: the caller passes dt from the IMU timestamps.

#include <Eigen/Core>
#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::lowlevel {

using AxisFlags = Eigen::Array<bool, 3, 1>;

// Declared (key, unit, default, range, help) in lowlevel/params/rate_control.yaml.
struct RateControlParams : DeclaredParams<RateControlParams> {
  Vec3 p;
  Vec3 i;
  Vec3 d;
  Vec3 integral_limit;
  double d_cutoff_hz;
  bool gyroscopic_feedforward;

  RateControlParams();
  static const ParamTable<RateControlParams>& declaration();
};

class RateController {
 public:
  struct Status {
    Vec3 proportional = Vec3::Zero();  // [rad/s^2] terms of the last update
    Vec3 integral = Vec3::Zero();
    Vec3 derivative = Vec3::Zero();
    Vec3 rate_derivative = Vec3::Zero();  // [rad/s^2] filtered d(rate)/dt
  };

  explicit RateController(const RateControlParams& params = RateControlParams());
  void setParams(const RateControlParams& params) { params_ = params; }
  const RateControlParams& params() const { return params_; }

  // Per axis: the mixer could not deliver more (positive) or less (negative) torque last time.
  void setSaturation(const AxisFlags& positive, const AxisFlags& negative);

  // Angular acceleration [rad/s^2] that drives `rate` to `rate_sp`; dt > 0 in seconds.
  Vec3 update(const Vec3& rate, const Vec3& rate_sp, double dt, bool landed);

  void resetIntegral() { integral_.setZero(); }
  // Forgets everything, including the derivative history (use after a gap or a mode change).
  void reset();
  const Status& status() const { return status_; }

 private:
  RateControlParams params_;
  Vec3 integral_ = Vec3::Zero();
  Vec3 previous_rate_ = Vec3::Zero();
  Vec3 rate_derivative_ = Vec3::Zero();
  bool has_previous_rate_ = false;
  AxisFlags saturated_positive_ = AxisFlags::Constant(false);
  AxisFlags saturated_negative_ = AxisFlags::Constant(false);
  Status status_;
};

}  // namespace sdlqr::lowlevel
