#include "sdlqr/sim/stress_params.hpp"

namespace sdlqr::sim {

PlantOverride::PlantOverride() { declaration().setDefaults(*this); }
WindParams::WindParams() { declaration().setDefaults(*this); }
AirborneStart::AirborneStart() { declaration().setDefaults(*this); }
ThrowEvent::ThrowEvent() { declaration().setDefaults(*this); }
PayloadDrop::PayloadDrop() { declaration().setDefaults(*this); }
SimStress::SimStress() { declaration().setDefaults(*this); }

SimStress SimStress::loadFromScenario(const std::string& scenario_path) {
  const YAML::Node root = loadYamlFile(scenario_path);
  return load(ConfigReader(root, "").child("sim"));
}

bool PlantOverride::changesNothing() const {
  return mass_scale == 1.0 && inertia_scale == Vec3::Ones() && thrust_scale == 1.0 &&
         motor_time_constant_scale == 1.0 && body_drag == 0.0;
}

const ParamTable<PlantOverride>& PlantOverride::declaration() {
  static const ParamTable<PlantOverride> table = [] {
    using P = PlantOverride;
    ParamTable<P> t("the simulated airframe relative to the vehicle file (the stack keeps assuming the file)");
    // Beyond these the rotors of a sane vehicle file could not lift it, or the model stops meaning much.
    t.number("mass_scale", &P::mass_scale, 1.0, "-", Range::closed(0.5, 1.8), "true mass over vehicle.mass");
    t.list("inertia_scale", &P::inertia_scale, {1.0, 1.0, 1.0}, "-", Range::closed(0.25, 4.0),
           "true inertia over vehicle.inertia_diag, per body axis");
    t.number("thrust_scale", &P::thrust_scale, 1.0, "-", Range::closed(0.5, 1.5),
             "thrust coefficient: produced over commanded rotor thrust");
    t.number("motor_time_constant_scale", &P::motor_time_constant_scale, 1.0, "-", Range::closed(0.0, 10.0),
             "true motor lag over vehicle.motor_time_constant");
    t.number("body_drag", &P::body_drag, 0.0, "N/(m/s)^2", Range::closed(0.0, 1.0),
             "quadratic frame drag in the relative wind, F = -c |v| v");
    return t;
  }();
  return table;
}

const ParamTable<WindParams>& WindParams::declaration() {
  static const ParamTable<WindParams> table = [] {
    using P = WindParams;
    ParamTable<P> t("steady wind plus Dryden-shaped turbulence (first order per axis, seeded)");
    t.list("steady", &P::steady, {0.0, 0.0, 0.0}, "m/s", Range::closed(-30.0, 30.0), "mean wind, world frame");
    t.list("gust_std", &P::gust_std, {0.0, 0.0, 0.0}, "m/s", Range::closed(0.0, 10.0),
           "stationary std of the turbulence per world axis");
    t.number("gust_time_constant", &P::gust_time_constant, 1.0, "s", Range::closed(0.01, 100.0),
             "correlation time L / V of the turbulence");
    return t;
  }();
  return table;
}

const ParamTable<AirborneStart>& AirborneStart::declaration() {
  static const ParamTable<AirborneStart> table = [] {
    using P = AirborneStart;
    ParamTable<P> t("start in the air in any state (position z > 0), instead of landed");
    t.list("position", &P::position, {0.0, 0.0, 0.0}, "m", Range::closed(-1000.0, 1000.0),
           "world; z = 0 keeps the landed start");
    t.list("attitude_deg", &P::attitude_deg, {0.0, 0.0, 0.0}, "deg", Range::closed(-360.0, 360.0),
           "roll, pitch, yaw (Z-Y-X); roll 180 is upside down");
    t.list("velocity", &P::velocity, {0.0, 0.0, 0.0}, "m/s", Range::closed(-30.0, 30.0), "world");
    t.list("body_rate", &P::body_rate, {0.0, 0.0, 0.0}, "rad/s", Range::closed(-30.0, 30.0), "body");
    t.flag("motors_spinning", &P::motors_spinning, true, "motors at hover thrust at the start (false: stopped)");
    t.check("position", [](const P& p) { return p.position.z() >= 0.0; }, "z must be >= 0 (the ground is z = 0)");
    return t;
  }();
  return table;
}

const ParamTable<ThrowEvent>& ThrowEvent::declaration() {
  static const ParamTable<ThrowEvent> table = [] {
    using P = ThrowEvent;
    ParamTable<P> t("held by a hand from the start, then thrown (or dropped) with the motors off");
    t.number("at", &P::at, -1.0, "s", Range::closed(-1.0, 3600.0), "the hand starts the throw; < 0: no throw");
    t.list("hold_position", &P::hold_position, {0.0, 0.0, 1.2}, "m", Range::closed(-1000.0, 1000.0),
           "world; where the hand holds the vehicle level until the throw");
    t.list("velocity", &P::velocity, {0.0, 0.0, 0.0}, "m/s", Range::closed(-20.0, 20.0), "world, at release");
    t.number("duration", &P::duration, 0.3, "s", Range::closed(0.0, 2.0), "of the hand's uniform push; 0: a drop");
    t.list("body_rate", &P::body_rate, {0.0, 0.0, 0.0}, "rad/s", Range::closed(-30.0, 30.0), "body, at release");
    t.check("hold_position", [](const P& p) { return p.hold_position.z() > 0.0; }, "z must be > 0 (held in the air)");
    t.check("duration", [](const P& p) { return p.duration > 0.0 || p.velocity.squaredNorm() == 0.0; },
            "a throw with a velocity needs a push longer than 0 s");
    return t;
  }();
  return table;
}

const ParamTable<PayloadDrop>& PayloadDrop::declaration() {
  static const ParamTable<PayloadDrop> table = [] {
    using P = PayloadDrop;
    ParamTable<P> t("a payload let go in flight: the plant's mass drops at a given time");
    t.number("at", &P::at, -1.0, "s", Range::closed(-1.0, 3600.0), "simulation time of the drop; < 0: none");
    t.number("mass_scale", &P::mass_scale, 0.85, "-", Range::closed(0.3, 1.0), "mass after the drop over mass before");
    return t;
  }();
  return table;
}

const ParamTable<SimStress>& SimStress::declaration() {
  static const ParamTable<SimStress> table = [] {
    using P = SimStress;
    ParamTable<P> t("the simulated world of one scenario: plant mismatch, wind, airborne start, throw");
    t.section("plant", &P::plant);
    t.section("wind", &P::wind);
    t.section("airborne_start", &P::airborne_start);
    t.section("throw", &P::throw_event);
    t.section("payload_drop", &P::payload_drop);
    t.check("throw", [](const P& p) { return !(p.throw_event.enabled() && p.airborne_start.enabled()); },
            "choose a throw or an airborne start, not both");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::sim
