#pragma once
// Settings of the plant simulator, read from the `sim:` section of a vehicle file. The airframe
// itself (mass, inertia, rotors, motor lag, rotor drag) is VehicleParams; this holds what only a
// simulated world has: rates, sensor noise, the battery, the ground, the initial pose, the seed.

#include <cstdint>
#include <string>

#include "sdlqr/config/config.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/math/types.hpp"

namespace sdlqr::sim {

// Noise of a MEMS IMU as agreed with the estimator (continuous-time densities).
struct ImuParams {
  int rate_hz = 1000;                     // [Hz] must divide physics_rate_hz
  double gyro_noise_density = 5e-4;       // [rad/s/sqrt(Hz)] white noise
  double accel_noise_density = 4e-3;      // [m/s^2/sqrt(Hz)] white noise
  double gyro_bias_random_walk = 2e-5;    // [rad/s^2/sqrt(Hz)]
  double accel_bias_random_walk = 2e-4;   // [m/s^3/sqrt(Hz)]
  double gyro_bias_initial_max = 0.02;    // [rad/s] initial bias uniform in +-max per axis
  double accel_bias_initial_max = 0.1;    // [m/s^2] initial bias uniform in +-max per axis
  double gyro_range = 34.9;               // [rad/s] readings clip here per axis (2000 deg/s)
  double accel_range = 156.9;             // [m/s^2] readings clip here per axis (16 g): touchdowns do
};

// Poses waiting for their publish time; validation keeps rate x latency well below it.
inline constexpr int kVioDelayLineCapacity = 16;

struct VioParams {
  int rate_hz = 30;                 // [Hz] capture rate
  double latency_min_s = 0.030;     // [s] capture-to-publish delay, uniform in [min, max]
  double latency_max_s = 0.050;     // [s]
  double position_std = 0.01;       // [m] per axis
  double attitude_std = 0.008;      // [rad] per axis, rotation-vector noise in the body frame
};

// LiPo pack feeding the motors. Thrust is calibrated at `calibration_charge` (the paper's 70 %):
// a fuller pack gives slightly more thrust than commanded, an emptier one less.
struct BatteryParams {
  bool enabled = true;                    // false: thrust_scale stays 1 (ideal supply)
  int cell_count = 3;                     // [-] cells in series
  double capacity_mah = 300.0;            // [mAh]
  double internal_resistance = 0.09;      // [ohm] whole pack
  double initial_charge = 0.75;           // [-] state of charge at start, (0, 1]
  double calibration_charge = 0.70;       // [-] charge at which commanded thrust is exact at hover
  double idle_power = 2.0;                // [W] electronics
  double rotor_power_coefficient = 16.0;  // [W/N^1.5] electrical power per rotor = k T^1.5
  double thrust_voltage_exponent = 2.0;   // [-] thrust ~ (terminal voltage)^n at a fixed command
};

// The ground is the plane z = 0, touched by the body origin. Contact is a constraint, not a spring:
// a landed vehicle rests exactly at z = 0 until the net force lifts it.
struct GroundParams {
  double crash_speed = 2.0;  // [m/s] touchdown faster than this (vertical) is a crash
  double crash_tilt = 1.0;   // [rad] touchdown tilted more than this (a flip) is a crash
};

// Bounds on accepted DISTURBANCE requests: a mistyped force must not launch the vehicle to orbit.
struct DisturbanceLimits {
  double max_force = 50.0;         // [N]
  double max_torque = 1.0;         // [N m]
  double max_duration = 600.0;     // [s]
  double max_stiffness = 1000.0;   // [N/m] hold spring
  double max_damping = 100.0;      // [N s/m] hold damper
};

struct SimParams {
  int physics_rate_hz = 1000;           // [Hz] RK4 rate, >= 1 kHz; its period must be a whole number of us
  int truth_rate_hz = 250;              // [Hz] SIM_TRUTH rate, must divide physics_rate_hz
  ImuParams imu;
  VioParams vio;
  BatteryParams battery;
  GroundParams ground;
  DisturbanceLimits disturbance;
  Vec3 initial_position = Vec3::Zero();  // [m] world; z = 0 starts landed, z > 0 starts in the air
  double initial_yaw = 0.0;              // [rad]
  int64_t seed = 1;                      // [-] noise seed; the same seed and inputs repeat a flight
  double gravity = kDefaultGravity;      // [m/s^2]

  int64_t physicsPeriodUs() const { return 1000000 / physics_rate_hz; }
  double physicsPeriod() const { return 1.0 / physics_rate_hz; }

  // Reads the `sim` mapping; throws ConfigError naming the key ("sim.vio.latency_max_s").
  static SimParams load(const ConfigReader& sim);
  // Empty when valid, else "key: reason" with the key relative to `sim`.
  std::string invalidReason() const;
  bool valid() const { return invalidReason().empty(); }
};

}  // namespace sdlqr::sim
