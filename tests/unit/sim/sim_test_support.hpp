#pragma once
// Shared set-ups for the simulator tests: an ideal supply (thrust exactly as commanded) so the
// physics tests compare against closed forms, and small helpers to command and run.

#include <Eigen/LU>  // inverse

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/sim/simulator.hpp"

namespace sdlqr::sim::test {

// Default parameters with the battery effect off: rotor thrust equals the motor-lag output.
inline SimParams idealParams() {
  SimParams p;
  p.battery.enabled = false;
  return p;
}

inline MotorCommand armed(const Vec4& thrust) {
  MotorCommand c;
  c.armed = true;
  c.mode = MotorMode::kRate;
  c.thrust = thrust;
  return c;
}

inline Vec4 hoverThrust(const VehicleParams& v, double gravity = kDefaultGravity) {
  return Vec4::Constant(v.hoverThrustPerRotor(gravity));
}

// Rotor thrusts giving collective thrust `collective` [N] and body torques `torque` [N m].
inline Vec4 thrustFor(const VehicleParams& v, double collective, const Vec3& torque) {
  Vec4 wrench;
  wrench << collective, torque;
  return v.effectiveness().inverse() * wrench;
}

inline BodyState airborne(const Vec3& position, const Vec3& velocity = Vec3::Zero(),
                          const Quat& orientation = identityQuat(), const Vec3& body_rate = Vec3::Zero()) {
  BodyState s;
  s.position = position;
  s.velocity = velocity;
  s.orientation = orientation;
  s.body_rate = body_rate;
  return s;
}

inline int64_t stepsFor(const Simulator& sim, double seconds) { return std::llround(seconds / sim.period()); }

inline void runFor(Simulator& sim, double seconds) {
  for (int64_t i = stepsFor(sim, seconds); i > 0; --i) sim.step();
}

}  // namespace sdlqr::sim::test
