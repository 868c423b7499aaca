#pragma once
// Body-rate PID, per axis, producing the angular acceleration the mixer should realize.
// Derivative on the measurement (a setpoint step gives no derivative kick) through a first-order
// low-pass; integral clamped and frozen in the direction the mixer reports as saturated; the
// integral is reset while landed, where it would only learn the contact torque of the ground.
// Plain C++ with no clock: the caller passes dt from the IMU timestamps.

#include <Eigen/Core>
#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::lowlevel {

using AxisFlags = Eigen::Array<bool, 3, 1>;

struct RateControlParams {
  // Tuned on a rigid body with the default inertia and a 30 ms motor lag: a 1 rad/s roll or
  // pitch step settles to 2 % in about 65 ms with < 1 % overshoot (tests/unit/lowlevel).
  // Yaw is slower on purpose: rotor drag gives it a tenth of the roll authority.
  Vec3 p = Vec3(120.0, 120.0, 12.0);            // [1/s] rad/s^2 per rad/s of rate error
  Vec3 i = Vec3(30.0, 30.0, 1.0);               // [1/s^2] rad/s^2 per rad of integrated error
  Vec3 d = Vec3(2.0, 2.0, 0.0);                 // [-] rad/s^2 per rad/s^2 of measured rate change
  Vec3 integral_limit = Vec3(30.0, 30.0, 10.0); // [rad/s^2] bound of the integral term
  double d_cutoff_hz = 40.0;                    // [Hz] low-pass on the derivative of the gyro
  bool gyroscopic_feedforward = true;           // add omega x J omega to the torque

  static RateControlParams load(const ConfigReader& reader);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
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
