#include "sdlqr/sim/sim_params.hpp"

#include <cmath>

namespace sdlqr::sim {

ImuParams::ImuParams() { declaration().setDefaults(*this); }
VioParams::VioParams() { declaration().setDefaults(*this); }
BatteryParams::BatteryParams() { declaration().setDefaults(*this); }
GroundParams::GroundParams() { declaration().setDefaults(*this); }
DisturbanceLimits::DisturbanceLimits() { declaration().setDefaults(*this); }
SimParams::SimParams() { declaration().setDefaults(*this); }

const ParamTable<ImuParams>& ImuParams::declaration() {
  static const ParamTable<ImuParams> table = [] {
    using P = ImuParams;
    ParamTable<P> t("MEMS IMU: noise and ranges as agreed with the estimator");
    t.integer("rate_hz", &P::rate_hz, 1000, "Hz", Range::closed(1, 100000), "IMU rate, divides physics_rate_hz");
    t.number("gyro_noise_density", &P::gyro_noise_density, 5e-4, "rad/s/sqrt(Hz)", Range::atLeast(0.0),
             "white noise (0.016 rad/s per sample at 1 kHz)");
    t.number("accel_noise_density", &P::accel_noise_density, 4e-3, "m/s^2/sqrt(Hz)", Range::atLeast(0.0),
             "white noise (0.13 m/s^2 per sample at 1 kHz)");
    t.number("gyro_bias_random_walk", &P::gyro_bias_random_walk, 2e-5, "rad/s^2/sqrt(Hz)", Range::atLeast(0.0),
             "gyro bias drift");
    t.number("accel_bias_random_walk", &P::accel_bias_random_walk, 2e-4, "m/s^3/sqrt(Hz)", Range::atLeast(0.0),
             "accelerometer bias drift");
    t.number("gyro_bias_initial_max", &P::gyro_bias_initial_max, 0.02, "rad/s", Range::atLeast(0.0),
             "initial bias uniform in +-max per axis");
    t.number("accel_bias_initial_max", &P::accel_bias_initial_max, 0.1, "m/s^2", Range::atLeast(0.0),
             "initial bias uniform in +-max per axis");
    t.number("gyro_range", &P::gyro_range, 34.9, "rad/s", Range::above(0.0), "readings clip here per axis (2000 deg/s)");
    // Below 2 g a hovering, manoeuvring vehicle would clip all the time.
    t.number("accel_range", &P::accel_range, 156.9, "m/s^2", Range::atLeast(20.0),
             "readings clip here per axis (16 g): touchdowns do");
    return t;
  }();
  return table;
}

const ParamTable<VioParams>& VioParams::declaration() {
  static const ParamTable<VioParams> table = [] {
    using P = VioParams;
    ParamTable<P> t("visual-inertial odometry poses: rate, delay, noise");
    t.integer("rate_hz", &P::rate_hz, 30, "Hz", Range::atLeast(1), "capture rate, at most physics_rate_hz");
    t.number("latency_min_s", &P::latency_min_s, 0.030, "s", Range::atLeast(0.0),
             "capture-to-publish delay, uniform in [min, max]");
    t.number("latency_max_s", &P::latency_max_s, 0.050, "s", Range::atLeast(0.0), "longest capture-to-publish delay");
    t.number("position_std", &P::position_std, 0.01, "m", Range::atLeast(0.0), "per axis");
    t.number("attitude_std", &P::attitude_std, 0.008, "rad", Range::atLeast(0.0), "per axis (rotation vector, body frame)");
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
  static const ParamTable<BatteryParams> table = [] {
    using P = BatteryParams;
    ParamTable<P> t("LiPo pack: thrust follows its terminal voltage");
    t.flag("enabled", &P::enabled, true, "false: ideal supply, thrust exactly as commanded");
    t.integer("cell_count", &P::cell_count, 3, "-", Range::closed(1, 14), "LiPo cells in series");
    t.number("capacity_mah", &P::capacity_mah, 300.0, "mAh", Range::above(0.0), "charge of a full pack");
    t.number("internal_resistance", &P::internal_resistance, 0.09, "ohm", Range::closed(0.0, 10.0), "whole pack");
    t.number("initial_charge", &P::initial_charge, 0.75, "-", Range::openClosed(0.0, 1.0), "state of charge at start");
    t.number("calibration_charge", &P::calibration_charge, 0.70, "-", Range::openClosed(0.0, 1.0),
             "thrust is exact in hover at this charge (paper §IV-B)");
    t.number("idle_power", &P::idle_power, 2.0, "W", Range::atLeast(0.0), "electronics");
    t.number("rotor_power_coefficient", &P::rotor_power_coefficient, 16.0, "W/N^1.5", Range::atLeast(0.0),
             "electrical power per rotor = k T^1.5");
    t.number("thrust_voltage_exponent", &P::thrust_voltage_exponent, 2.0, "-", Range::closed(0.0, 4.0),
             "thrust ~ voltage^n at a fixed command");
    return t;
  }();
  return table;
}

const ParamTable<GroundParams>& GroundParams::declaration() {
  static const ParamTable<GroundParams> table = [] {
    using P = GroundParams;
    ParamTable<P> t("the ground plane z = 0");
    t.number("crash_speed", &P::crash_speed, 2.0, "m/s", Range::above(0.0), "touchdown sink speed above this is a crash");
    t.number("crash_tilt", &P::crash_tilt, 1.0, "rad", Range::openClosed(0.0, M_PI),
             "touchdown tilt above this (a flip) is a crash");
    return t;
  }();
  return table;
}

const ParamTable<DisturbanceLimits>& DisturbanceLimits::declaration() {
  static const ParamTable<DisturbanceLimits> table = [] {
    using P = DisturbanceLimits;
    ParamTable<P> t("bounds of accepted DISTURBANCE requests");
    t.number("max_force", &P::max_force, 50.0, "N", Range::above(0.0), "larger DISTURBANCE forces are rejected");
    t.number("max_torque", &P::max_torque, 1.0, "N m", Range::above(0.0), "larger DISTURBANCE torques are rejected");
    t.number("max_duration", &P::max_duration, 600.0, "s", Range::openClosed(0.0, 86400.0), "longest DISTURBANCE");
    t.number("max_stiffness", &P::max_stiffness, 1000.0, "N/m", Range::atLeast(0.0), "MODE_HOLD spring");
    t.number("max_damping", &P::max_damping, 100.0, "N s/m", Range::atLeast(0.0), "MODE_HOLD damper");
    return t;
  }();
  return table;
}

const ParamTable<SimParams>& SimParams::declaration() {
  static const ParamTable<SimParams> table = [] {
    using P = SimParams;
    ParamTable<P> t("plant simulator (sdlqr-sim); sensor noise defaults are the ones the estimator assumes");
    t.integer("physics_rate_hz", &P::physics_rate_hz, 1000, "Hz", Range::closed(1000, 100000),
              "RK4 rate, whole-microsecond period");
    t.integer("truth_rate_hz", &P::truth_rate_hz, 250, "Hz", Range::atLeast(1), "SIM_TRUTH rate, divides physics_rate_hz");
    t.section("imu", &P::imu);
    t.section("vio", &P::vio);
    t.section("battery", &P::battery);
    t.section("ground", &P::ground);
    t.section("disturbance", &P::disturbance);
    t.list("initial_position", &P::initial_position, {0.0, 0.0, 0.0}, "m", Range::finite(),
           "world; z = 0 starts landed, z > 0 in the air");
    t.number("initial_yaw", &P::initial_yaw, 0.0, "rad", Range::finite(), "heading at start");
    t.integer("seed", &P::seed, 1, "-", Range::atLeast(0), "noise seed (--seed overrides)");
    t.number("gravity", &P::gravity, kDefaultGravity, "m/s^2", Range::open(0.0, 100.0), "gravity of the simulated world");
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
