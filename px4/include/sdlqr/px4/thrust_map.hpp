#pragma once
// sdlqr's collective thrust c (mass-normalized, m/s^2, along body z) <-> PX4's normalized
// collective thrust T in [0, 1] (SET_ATTITUDE_TARGET.thrust). PX4's multicopter rate controller
// passes T to the mixer, whose thrust model (THR_MDL_FAC = k) makes the relative thrust
//   f(T) = (1 - k) T + k T^2
// With the vehicle hovering at T = h (the hover throttle) the thrust is g, so c = g f(T) / f(h)
// and, back, T = f^-1(c f(h) / g) clamped to [0, 1]. With k = 0 (THR_MDL_FAC set right on PX4, the
// default here) this is PX4's own law T = c h / g (mc_pos_control PositionControl.cpp).
//
// h is identified from a hover flown with a guess (docs/px4.md): in steady flight the vertical
// acceleration is a_z = c cos(tilt) - g, so over the samples of a hover 1 / f(h) is the least-
// squares fit of (a_z + g) = (g f(T) cos(tilt)) / f(h), and h follows. Pure, no allocation.

#include <string>
#include <vector>

#include "sdlqr/config/param_table.hpp"

namespace sdlqr::px4 {

struct ThrustMap {
  double hover_throttle;  // h [-] T at which the vehicle hovers
  double curve;           // k [-] PX4's THR_MDL_FAC: 0 linear, 1 quadratic

  ThrustMap();
  static const ParamTable<ThrustMap>& declaration();
};

double relativeThrust(double normalized, double curve);            // f(T)
double normalizedThrust(double c, const ThrustMap& map, double g);  // T in [0, 1] for c [m/s^2]
double massNormalizedThrust(double normalized, const ThrustMap& map, double g);  // c for T

// One sample of a hover: the normalized thrust sent, the vertical acceleration that followed
// [m/s^2, world z up] and the tilt [rad] at the time.
struct HoverSample {
  double normalized_thrust = 0.0;
  double vertical_acceleration = 0.0;
  double tilt = 0.0;
};

struct HoverFit {
  double hover_throttle = 0.0;  // NaN when the samples cannot give one
  int samples = 0;
  double residual_rms = 0.0;    // [m/s^2] of (a_z + g) against the fit
  std::string error;            // why there is no fit
};

// The hover throttle of the samples under thrust model `curve`.
HoverFit fitHoverThrottle(const std::vector<HoverSample>& samples, double curve, double g);

}  // namespace sdlqr::px4
