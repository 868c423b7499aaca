#pragma once
// What a scenario changes in the simulated world only (the `sim:` key of a scenario file): a plant
// that differs from the vehicle file the stack flies on, wind, an airborne start and a throw. The
// controller, estimator and bodyrate loop never see these values: they fly the vehicle file.
// Every default leaves the world exactly as without the key (scales of 1, no wind, a landed start,
// no throw), so scenarios without it fly bit for bit as before.
//
//   sim:
//     plant: {mass_scale: 1.2, inertia_scale: [1, 1, 1], thrust_scale: 1.0, motor_time_constant_scale: 1.0}
//     wind: {steady: [2, 0, 0], gust_std: [1, 1, 0.5], gust_time_constant: 1.0, body_drag: 0.01}
//     airborne_start: {position: [0, 0, 3], attitude_deg: [180, 0, 0], velocity: [0, 0, 0], body_rate: [0, 0, 0]}
//     throw: {at: 3.0, hold_position: [0, 0, 1.2], velocity: [1, 0, 3], duration: 0.3, body_rate: [0, 0, 0]}
//     payload_drop: {at: 12.0, mass_scale: 0.85}

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::sim {

// The airframe as it really is, relative to the vehicle file the stack assumes.
struct PlantOverride {
  double mass_scale;
  Vec3 inertia_scale;
  double thrust_scale;                // thrust coefficient: produced thrust per commanded thrust
  double motor_time_constant_scale;
  double body_drag;                   // [N/(m/s)^2] quadratic drag of the frame in the relative wind

  PlantOverride();
  static const ParamTable<PlantOverride>& declaration();
  bool changesNothing() const;
};

// Steady wind plus turbulence: per world axis a first-order Gauss-Markov process (the spectrum of
// the Dryden longitudinal gust, 1 / (1 + tau s), with tau = L / V) of stationary std `gust_std`,
// drawn from its own random stream of the simulator's seed. The wind acts through the relative
// air velocity on the rotor drag and the frame drag.
struct WindParams {
  Vec3 steady;              // [m/s] world
  Vec3 gust_std;            // [m/s] world, 0: no turbulence
  double gust_time_constant;  // [s]

  WindParams();
  static const ParamTable<WindParams>& declaration();
  bool enabled() const { return steady.squaredNorm() > 0.0 || gust_std.squaredNorm() > 0.0; }
};

// The vehicle starts in the air in any state, motors at hover thrust (as if it had been flying)
// or stopped. position z = 0 (the default) keeps the landed start of the vehicle file.
struct AirborneStart {
  Vec3 position;       // [m] world
  Vec3 attitude_deg;   // [deg] roll, pitch, yaw (Z-Y-X); roll 180 is upside down
  Vec3 velocity;       // [m/s] world
  Vec3 body_rate;      // [rad/s] body
  bool motors_spinning;

  AirborneStart();
  static const ParamTable<AirborneStart>& declaration();
  bool enabled() const { return position.z() > 0.0; }
};

// A hand holds the vehicle level at hold_position from the start; at `at` it accelerates it
// uniformly over `duration` to `velocity` and lets go (a drop: velocity 0, duration 0), the
// vehicle then spinning at body_rate. at < 0 (the default): no throw.
struct ThrowEvent {
  double at;             // [s] simulation time the throw begins
  Vec3 hold_position;    // [m] world, z > 0
  Vec3 velocity;         // [m/s] world, at release
  double duration;       // [s] of the hand's push
  Vec3 body_rate;        // [rad/s] body, at release

  ThrowEvent();
  static const ParamTable<ThrowEvent>& declaration();
  bool enabled() const { return at >= 0.0; }
  double releaseTime() const { return at + duration; }
};

// A payload let go in flight: from `at` on the plant's mass is `mass_scale` times what it was (a
// payload hung at the centre of mass: the inertia is kept). at < 0 (the default): none.
struct PayloadDrop {
  double at;          // [s] simulation time of the drop
  double mass_scale;  // [-] mass after over mass before

  PayloadDrop();
  static const ParamTable<PayloadDrop>& declaration();
  bool enabled() const { return at >= 0.0; }
};

struct SimStress : DeclaredParams<SimStress> {
  PlantOverride plant;
  WindParams wind;
  AirborneStart airborne_start;
  ThrowEvent throw_event;
  PayloadDrop payload_drop;

  SimStress();
  static const ParamTable<SimStress>& declaration();
  // load(): a scenario's `sim` mapping, its ConfigError naming the key ("sim.wind.gust_std[1]").
  // The `sim` mapping of a scenario file (the simulator reads no other part of it: the scenario's
  // events are the mission's, which checks the whole file).
  static SimStress loadFromScenario(const std::string& scenario_path);
};

}  // namespace sdlqr::sim
