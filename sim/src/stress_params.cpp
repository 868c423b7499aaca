#include "sdlqr/sim/stress_params.hpp"

#include "stress_params_rows.hpp"

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
  static const ParamTable<PlantOverride> table = plantOverrideRows();
  return table;
}

const ParamTable<WindParams>& WindParams::declaration() {
  static const ParamTable<WindParams> table = windParamsRows();
  return table;
}

const ParamTable<AirborneStart>& AirborneStart::declaration() {
  static const ParamTable<AirborneStart> table = [] {
    using P = AirborneStart;
    ParamTable<P> t = airborneStartRows();
    t.check("position", [](const P& p) { return p.position.z() >= 0.0; }, "z must be >= 0 (the ground is z = 0)");
    return t;
  }();
  return table;
}

const ParamTable<ThrowEvent>& ThrowEvent::declaration() {
  static const ParamTable<ThrowEvent> table = [] {
    using P = ThrowEvent;
    ParamTable<P> t = throwEventRows();
    t.check("hold_position", [](const P& p) { return p.hold_position.z() > 0.0; }, "z must be > 0 (held in the air)");
    t.check("duration", [](const P& p) { return p.duration > 0.0 || p.velocity.squaredNorm() == 0.0; },
            "a throw with a velocity needs a push longer than 0 s");
    return t;
  }();
  return table;
}

const ParamTable<PayloadDrop>& PayloadDrop::declaration() {
  static const ParamTable<PayloadDrop> table = payloadDropRows();
  return table;
}

const ParamTable<SimStress>& SimStress::declaration() {
  static const ParamTable<SimStress> table = [] {
    using P = SimStress;
    ParamTable<P> t = simStressRows();
    t.check("throw", [](const P& p) { return !(p.throw_event.enabled() && p.airborne_start.enabled()); },
            "choose a throw or an airborne start, not both");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::sim
