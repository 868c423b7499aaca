#pragma once
// Ground contact seen through the IMU alone.
//   at rest:  low-passed specific force ~ g and low-passed rotation ~ 0. Steady hover looks the
//             same, so the callers add what only the ground explains: a thrust command below
//             hover (auto-disarm) or a commanded descent that does not happen (failsafe).
//   impact:   one sample of specific force along body z well above what the rotors produce.
//   body z:   the low-passed specific force along body z, for the caller to compare with the
//             thrust it commands: well above it (support_margin), something else carries part of
//             the weight.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::lowlevel {

// Declared (key, unit, default, range, help) in lowlevel/params/ground_detector.yaml.
struct GroundDetectorParams : DeclaredParams<GroundDetectorParams> {
  double filter_cutoff_hz;
  double accel_tolerance;
  double gyro_tolerance;
  double impact_threshold;
  double support_margin;
  double landed_thrust_ratio;
  double landed_time;

  GroundDetectorParams();
  static const ParamTable<GroundDetectorParams>& declaration();
};

class GroundDetector {
 public:
  GroundDetector(const GroundDetectorParams& params, double gravity);

  // rotor_specific_force [m/s^2]: collective thrust the rotors produce now, over the mass.
  void update(const Vec3& gyro, const Vec3& accel, double rotor_specific_force, double dt);
  bool atRest() const { return at_rest_; }
  bool impact() const { return impact_; }
  double filteredBodyZ() const { return body_z_force_; }
  double filteredSpecificForce() const { return specific_force_; }
  double filteredRotationRate() const { return rotation_rate_; }
  const GroundDetectorParams& params() const { return params_; }
  void reset();

 private:
  GroundDetectorParams params_;
  double gravity_;
  bool initialized_ = false;
  double specific_force_ = 0.0;
  double rotation_rate_ = 0.0;
  bool at_rest_ = false;
  bool impact_ = false;
  double body_z_force_ = 0.0;  // [m/s^2] low-passed accel z
};

}  // namespace sdlqr::lowlevel
