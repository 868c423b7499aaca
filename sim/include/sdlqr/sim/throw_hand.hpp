#pragma once
// The hand of a throw (ThrowEvent): it holds the vehicle level and still at hold_position, then
// pushes it with a uniform acceleration for `duration` and lets go. While held, the motion is
// prescribed (the hand is far stronger than the rotors); the IMU feels the hand's acceleration.

#include "sdlqr/sim/rigid_body.hpp"
#include "sdlqr/sim/stress_params.hpp"

namespace sdlqr::sim {

class ThrowHand {
 public:
  ThrowHand(const ThrowEvent& event, double yaw);

  // True while the hand holds the vehicle at t [s] (the release step is the last held one).
  bool holds(double t) const { return event_.enabled() && t <= event_.releaseTime(); }
  // The held state at t; at the release time it carries the release body rate.
  BodyState stateAt(double t) const;
  // [m/s^2] world, the hand's acceleration at t.
  Vec3 accelerationAt(double t) const;

 private:
  ThrowEvent event_;
  Quat orientation_;
};

}  // namespace sdlqr::sim
