#pragma once
// Settings of the plant simulator, read from the `sim:` section of a vehicle file. The airframe
// itself (mass, inertia, rotors, motor lag, rotor drag) is VehicleParams; this holds what only a
// simulated world has: rates, sensor noise, the battery, the ground, the initial pose, the seed.

#include <cstdint>
#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::sim {

// Each struct's members are declared once (key, unit, default, range, help) in
// sim/params/sim_params.yaml (the rules across keys: sim_params.cpp); the default constructors take
// the defaults from there.

// Noise of a MEMS IMU as agreed with the estimator (continuous-time densities).
struct ImuParams {
  int rate_hz;  // must divide physics_rate_hz
  double gyro_noise_density;
  double accel_noise_density;
  double gyro_bias_random_walk;
  double accel_bias_random_walk;
  double gyro_bias_initial_max;
  double accel_bias_initial_max;
  double gyro_range;
  double accel_range;

  ImuParams();
  static const ParamTable<ImuParams>& declaration();
};

// Poses waiting for their publish time; validation keeps rate x latency well below it.
inline constexpr int kVioDelayLineCapacity = 16;

struct VioParams {
  int rate_hz;
  double latency_min_s;  // capture-to-publish delay, uniform in [min, max]
  double latency_max_s;
  double position_std;
  double attitude_std;

  VioParams();
  static const ParamTable<VioParams>& declaration();
};

// LiPo pack feeding the motors. Thrust is calibrated at `calibration_charge` (the paper's 70 %):
// a fuller pack gives slightly more thrust than commanded, an emptier one less.
struct BatteryParams {
  bool enabled;  // false: thrust_scale stays 1 (ideal supply)
  int cell_count;
  double capacity_mah;
  double internal_resistance;
  double initial_charge;
  double calibration_charge;
  double idle_power;
  double rotor_power_coefficient;
  double thrust_voltage_exponent;

  BatteryParams();
  static const ParamTable<BatteryParams>& declaration();
};

// The ground is the plane z = 0, touched by the body origin. Contact is a constraint, not a spring:
// a landed vehicle rests exactly at z = 0 until the net force lifts it.
struct GroundParams {
  double crash_speed;
  double crash_tilt;

  GroundParams();
  static const ParamTable<GroundParams>& declaration();
};

// Bounds on accepted DISTURBANCE requests: a mistyped force must not launch the vehicle to orbit.
struct DisturbanceLimits {
  double max_force;
  double max_torque;
  double max_duration;
  double max_stiffness;
  double max_damping;

  DisturbanceLimits();
  static const ParamTable<DisturbanceLimits>& declaration();
};

struct SimParams : DeclaredParams<SimParams> {
  int physics_rate_hz;
  int truth_rate_hz;
  ImuParams imu;
  VioParams vio;
  BatteryParams battery;
  GroundParams ground;
  DisturbanceLimits disturbance;
  Vec3 initial_position;
  double initial_yaw;
  int64_t seed;  // the same seed and inputs repeat a flight
  double gravity;

  int64_t physicsPeriodUs() const { return 1000000 / physics_rate_hz; }
  double physicsPeriod() const { return 1.0 / physics_rate_hz; }

  SimParams();
  static const ParamTable<SimParams>& declaration();
};

}  // namespace sdlqr::sim
