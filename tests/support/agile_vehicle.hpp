#pragma once
// The agile vehicle of the tests (config/agile752.yaml): its lqr limits and rotor drag, the drag in
// the controllers' model or not (lqr.model_rotor_drag), and its benchmarks' 3 m circle and figure
// eight at a speed.

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/transition.hpp"

namespace sdlqr::test {

inline LqrParams agileLqr(bool drag_modelled) {
  LqrParams lqr;
  lqr.gravity = kDefaultGravity;
  lqr.c_max = 45.0;
  lqr.omega_max = 15.0;
  lqr.vehicle_rotor_drag = Vec3(0.69, 0.69, 1.34);
  lqr.model_rotor_drag = drag_modelled;
  return lqr;
}

// Its transitions (controller.transition): planned first within half the limits.
inline trajectory::TransitionParams agileTransitions() {
  trajectory::TransitionParams params;
  params.gentle_fraction = 0.5;
  return params;
}

// 3 m radius, level at 2 m, centred on the origin, at `speed` [m/s].
inline Trajectory agileCircle(double speed) {
  trajectory::ClosedPathSpec circle;
  circle.size = 3.0;
  circle.speed = speed;
  circle.center = Vec3(0.0, 0.0, 2.0);
  return trajectory::sampleClosedPath(circle, kDefaultGravity);
}

// Its figure eight (config/compare/agile_lemniscate_sweep.yaml): 3 m half-width, level at 2 m,
// centred on the origin, at peak `speed` [m/s].
inline Trajectory agileLemniscate(double speed) {
  trajectory::ClosedPathSpec lemniscate;
  lemniscate.shape = trajectory::ClosedPathShape::kLemniscate;
  lemniscate.size = 3.0;
  lemniscate.speed = speed;
  lemniscate.center = Vec3(0.0, 0.0, 2.0);
  return trajectory::sampleClosedPath(lemniscate, kDefaultGravity);
}

}  // namespace sdlqr::test
