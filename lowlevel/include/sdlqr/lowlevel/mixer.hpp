#pragma once
// Control allocation: collective thrust and body torques to four rotor thrusts through the
// pseudo-inverse of the effectiveness matrix (geometry: VehicleParams::effectiveness()), then
// sequential desaturation that keeps what matters most for staying upright:
//   1. roll/pitch torque is kept whole; only if even the full rotor range cannot produce it,
//      the roll/pitch vector is scaled down (direction kept);
//   2. yaw torque is added as far as it fits while the collective stays within
//      `yaw_collective_share` of the demand (or of what roll/pitch alone needed);
//   3. the collective thrust is shifted to the nearest value that keeps every rotor in range.
// Every result lies within [min_thrust, max_thrust] per rotor.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/rate_control.hpp"

namespace sdlqr::lowlevel {

// Declared (key, unit, default, range, help) in lowlevel/params/mixer.yaml.
struct MixerParams : DeclaredParams<MixerParams> {
  double yaw_collective_share;

  MixerParams();
  static const ParamTable<MixerParams>& declaration();
};

struct MixerResult {
  Vec4 thrust = Vec4::Zero();     // [N] per rotor, within limits
  double collective = 0.0;        // [N] what the rotors produce, E * thrust
  Vec3 torque = Vec3::Zero();     // [N m]
  double roll_pitch_scale = 1.0;  // [-] share of the demanded roll/pitch torque delivered
  double yaw_scale = 1.0;         // [-] share of the demanded yaw torque delivered
  bool collective_limited = false;
  AxisFlags saturated_positive = AxisFlags::Constant(false);  // torque axis short of a positive demand
  AxisFlags saturated_negative = AxisFlags::Constant(false);
  bool saturated() const { return saturated_positive.any() || saturated_negative.any() || collective_limited; }
};

class Mixer {
 public:
  // Throws std::invalid_argument when a rotor does not lift with the collective (then shifting
  // the collective cannot desaturate) or the limits are empty.
  Mixer(const Mat44& effectiveness, double min_thrust, double max_thrust, const MixerParams& params = MixerParams());

  void setThrustLimits(double min_thrust, double max_thrust);
  MixerResult mix(double collective, const Vec3& torque) const;

  const Mat44& effectiveness() const { return effectiveness_; }
  const Mat44& allocation() const { return allocation_; }
  double minThrust() const { return min_thrust_; }
  double maxThrust() const { return max_thrust_; }

 private:
  // Largest k in [0, 1] for which thrust = base + k * direction + collective_column * F stays in
  // range for some F within [collective_low, collective_high].
  double largestFeasibleScale(const Vec4& base, const Vec4& direction, double collective_low,
                              double collective_high) const;
  // Collective range that keeps `base + collective_column * F` within the rotor limits.
  void collectiveInterval(const Vec4& base, double* low, double* high) const;

  Mat44 effectiveness_;
  Mat44 allocation_;  // pseudo-inverse of effectiveness_
  Vec4 collective_column_;
  Vec4 inverse_collective_column_;  // 1 / each rotor's share of the collective
  double min_thrust_;
  double max_thrust_;
  MixerParams params_;
};

}  // namespace sdlqr::lowlevel
