#include "sdlqr/sim/sim_params.hpp"

#include <cmath>

#include "sim_params_rows.hpp"

namespace sdlqr::sim {

ImuParams::ImuParams() { declaration().setDefaults(*this); }
VioParams::VioParams() { declaration().setDefaults(*this); }
BatteryParams::BatteryParams() { declaration().setDefaults(*this); }
GroundParams::GroundParams() { declaration().setDefaults(*this); }
DisturbanceLimits::DisturbanceLimits() { declaration().setDefaults(*this); }
SimParams::SimParams() { declaration().setDefaults(*this); }

const ParamTable<ImuParams>& ImuParams::declaration() {
  static const ParamTable<ImuParams> table = imuParamsRows();
  return table;
}

const ParamTable<VioParams>& VioParams::declaration() {
  static const ParamTable<VioParams> table = [] {
    using P = VioParams;
    ParamTable<P> t = vioParamsRows();
    t.check("latency_max_s", [](const P& v) { return v.latency_max_s >= v.latency_min_s; }, "must be >= latency_min_s");
    // A real VIO publishes in capture order; a latency spread below one period keeps that true.
    t.check("latency_max_s", [](const P& v) { return v.latency_max_s - v.latency_min_s < 1.0 / v.rate_hz; },
            "latency spread must stay below one VIO period");
    t.check("latency_max_s", [](const P& v) { return v.latency_max_s * v.rate_hz + 2.0 <= kVioDelayLineCapacity; },
            "too many poses in flight for the delay line (rate x latency)");
    return t;
  }();
  return table;
}

const ParamTable<BatteryParams>& BatteryParams::declaration() {
  static const ParamTable<BatteryParams> table = batteryParamsRows();
  return table;
}

const ParamTable<GroundParams>& GroundParams::declaration() {
  static const ParamTable<GroundParams> table = groundParamsRows();
  return table;
}

const ParamTable<DisturbanceLimits>& DisturbanceLimits::declaration() {
  static const ParamTable<DisturbanceLimits> table = disturbanceLimitsRows();
  return table;
}

const ParamTable<SimParams>& SimParams::declaration() {
  static const ParamTable<SimParams> table = [] {
    using P = SimParams;
    ParamTable<P> t = simParamsRows();
    t.check("physics_rate_hz", [](const P& p) { return 1000000 % p.physics_rate_hz == 0; },
            "must give a whole-microsecond period");
    t.check("truth_rate_hz", [](const P& p) { return p.physics_rate_hz % p.truth_rate_hz == 0; },
            "must divide physics_rate_hz");
    t.check("imu.rate_hz", [](const P& p) { return p.physics_rate_hz % p.imu.rate_hz == 0; },
            "must divide physics_rate_hz");
    t.check("vio.rate_hz", [](const P& p) { return p.vio.rate_hz <= p.physics_rate_hz; },
            "must be in [1, physics_rate_hz]");
    t.check("initial_position", [](const P& p) { return p.initial_position.z() >= 0.0; },
            "z must be >= 0 (the ground is z = 0)");
    return t;
  }();
  return table;
}

}  // namespace sdlqr::sim
