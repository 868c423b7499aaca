#include "sdlqr/sim/throw_hand.hpp"

#include <algorithm>

namespace sdlqr::sim {

ThrowHand::ThrowHand(const ThrowEvent& event, double yaw) : event_(event), orientation_(quat::fromYaw(yaw)) {}

Vec3 ThrowHand::accelerationAt(double t) const {
  if (event_.duration <= 0.0 || t < event_.at || t > event_.releaseTime()) return Vec3::Zero();
  return event_.velocity / event_.duration;
}

BodyState ThrowHand::stateAt(double t) const {
  BodyState s;
  s.orientation = orientation_;
  const double pushed = std::clamp(t - event_.at, 0.0, event_.duration);
  const Vec3 acceleration = event_.duration > 0.0 ? Vec3(event_.velocity / event_.duration) : Vec3::Zero();
  s.position = event_.hold_position + 0.5 * pushed * pushed * acceleration;
  s.velocity = pushed * acceleration;
  if (t >= event_.releaseTime()) s.body_rate = event_.body_rate;
  return s;
}

}  // namespace sdlqr::sim
