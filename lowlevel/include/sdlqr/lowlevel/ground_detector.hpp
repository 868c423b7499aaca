#pragma once
// Ground contact seen through the IMU alone.
//   at rest:  low-passed specific force ~ g and low-passed rotation ~ 0. Steady hover looks the
//             same, so the callers add what only the ground explains: a thrust command below
//             hover (auto-disarm) or a commanded descent that does not happen (failsafe).
//   impact:   one sample of specific force along body z well above what the rotors produce.

#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::lowlevel {

struct GroundDetectorParams {
  double filter_cutoff_hz = 5.0;      // [Hz] low-pass on |specific force| and |rotation rate|
  double accel_tolerance = 0.5;       // [m/s^2] at rest when | |f| - g | is below this
  double gyro_tolerance = 0.2;        // [rad/s] and |omega| below this
  double impact_threshold = 5.0;      // [m/s^2] body-z specific force above the rotors' share
  double landed_thrust_ratio = 0.8;   // [-] "thrust below hover": command < ratio * hover thrust
  double landed_time = 1.0;           // [s] at rest with thrust below hover before auto-disarm

  static GroundDetectorParams load(const ConfigReader& reader);
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

class GroundDetector {
 public:
  GroundDetector(const GroundDetectorParams& params, double gravity);

  // rotor_specific_force [m/s^2]: collective thrust the rotors produce now, over the mass.
  void update(const Vec3& gyro, const Vec3& accel, double rotor_specific_force, double dt);
  bool atRest() const { return at_rest_; }
  bool impact() const { return impact_; }
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
};

}  // namespace sdlqr::lowlevel
