#include "sdlqr/sim/ground.hpp"

namespace sdlqr::sim {

BodyState restingOnGround(const BodyState& touching) {
  BodyState rest;
  rest.position = Vec3(touching.position.x(), touching.position.y(), 0.0);
  rest.orientation = quat::fromYaw(quat::yaw(touching.orientation));
  return rest;
}

bool isCrash(const BodyState& touching, const GroundParams& ground) {
  const double sink_speed = -touching.velocity.z();
  return sink_speed > ground.crash_speed || quat::tilt(touching.orientation) > ground.crash_tilt;
}

}  // namespace sdlqr::sim
