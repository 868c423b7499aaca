#include "sdlqr/sim/sim_params.hpp"

#include <cmath>

namespace sdlqr::sim {

namespace {

bool finiteAtLeast(double value, double low) { return std::isfinite(value) && value >= low; }
bool finiteAbove(double value, double low) { return std::isfinite(value) && value > low; }

std::string imuInvalidReason(const ImuParams& imu, int physics_rate_hz) {
  if (imu.rate_hz <= 0 || physics_rate_hz % imu.rate_hz != 0) return "imu.rate_hz: must divide physics_rate_hz";
  if (!finiteAtLeast(imu.gyro_noise_density, 0.0)) return "imu.gyro_noise_density: must be >= 0";
  if (!finiteAtLeast(imu.accel_noise_density, 0.0)) return "imu.accel_noise_density: must be >= 0";
  if (!finiteAtLeast(imu.gyro_bias_random_walk, 0.0)) return "imu.gyro_bias_random_walk: must be >= 0";
  if (!finiteAtLeast(imu.accel_bias_random_walk, 0.0)) return "imu.accel_bias_random_walk: must be >= 0";
  if (!finiteAtLeast(imu.gyro_bias_initial_max, 0.0)) return "imu.gyro_bias_initial_max: must be >= 0";
  if (!finiteAtLeast(imu.accel_bias_initial_max, 0.0)) return "imu.accel_bias_initial_max: must be >= 0";
  if (!finiteAbove(imu.gyro_range, 0.0)) return "imu.gyro_range: must be > 0";
  // Below 2 g a hovering, manoeuvring vehicle would clip all the time.
  if (!(std::isfinite(imu.accel_range) && imu.accel_range >= 20.0)) return "imu.accel_range: must be >= 20 m/s^2";
  return {};
}

std::string vioInvalidReason(const VioParams& vio, int physics_rate_hz) {
  if (vio.rate_hz <= 0 || vio.rate_hz > physics_rate_hz) return "vio.rate_hz: must be in [1, physics_rate_hz]";
  if (!finiteAtLeast(vio.latency_min_s, 0.0)) return "vio.latency_min_s: must be >= 0";
  if (!(std::isfinite(vio.latency_max_s) && vio.latency_max_s >= vio.latency_min_s)) {
    return "vio.latency_max_s: must be >= latency_min_s";
  }
  // A real VIO publishes in capture order; a latency spread below one period keeps that true.
  if (vio.latency_max_s - vio.latency_min_s >= 1.0 / vio.rate_hz) {
    return "vio.latency_max_s: latency spread must stay below one VIO period";
  }
  if (vio.latency_max_s * vio.rate_hz + 2.0 > kVioDelayLineCapacity) {
    return "vio.latency_max_s: too many poses in flight for the delay line (rate x latency)";
  }
  if (!finiteAtLeast(vio.position_std, 0.0)) return "vio.position_std: must be >= 0";
  if (!finiteAtLeast(vio.attitude_std, 0.0)) return "vio.attitude_std: must be >= 0";
  return {};
}

std::string batteryInvalidReason(const BatteryParams& b) {
  if (b.cell_count < 1 || b.cell_count > 14) return "battery.cell_count: must be in [1, 14]";
  if (!finiteAbove(b.capacity_mah, 0.0)) return "battery.capacity_mah: must be > 0";
  if (!finiteAtLeast(b.internal_resistance, 0.0) || b.internal_resistance > 10.0) {
    return "battery.internal_resistance: must be in [0, 10] ohm";
  }
  if (!(finiteAbove(b.initial_charge, 0.0) && b.initial_charge <= 1.0)) return "battery.initial_charge: must be in (0, 1]";
  if (!(finiteAbove(b.calibration_charge, 0.0) && b.calibration_charge <= 1.0)) {
    return "battery.calibration_charge: must be in (0, 1]";
  }
  if (!finiteAtLeast(b.idle_power, 0.0)) return "battery.idle_power: must be >= 0";
  if (!finiteAtLeast(b.rotor_power_coefficient, 0.0)) return "battery.rotor_power_coefficient: must be >= 0";
  if (!(finiteAtLeast(b.thrust_voltage_exponent, 0.0) && b.thrust_voltage_exponent <= 4.0)) {
    return "battery.thrust_voltage_exponent: must be in [0, 4]";
  }
  return {};
}

std::string disturbanceInvalidReason(const DisturbanceLimits& d) {
  if (!finiteAbove(d.max_force, 0.0)) return "disturbance.max_force: must be > 0";
  if (!finiteAbove(d.max_torque, 0.0)) return "disturbance.max_torque: must be > 0";
  if (!finiteAbove(d.max_duration, 0.0) || d.max_duration > 86400.0) return "disturbance.max_duration: must be in (0, 86400] s";
  if (!finiteAtLeast(d.max_stiffness, 0.0)) return "disturbance.max_stiffness: must be >= 0";
  if (!finiteAtLeast(d.max_damping, 0.0)) return "disturbance.max_damping: must be >= 0";
  return {};
}

}  // namespace

SimParams SimParams::load(const ConfigReader& sim) {
  sim.allowOnly({"physics_rate_hz", "truth_rate_hz", "imu", "vio", "battery", "ground", "disturbance",
                 "initial_position", "initial_yaw", "seed", "gravity"});
  SimParams p;
  sim.read("physics_rate_hz", p.physics_rate_hz);
  sim.read("truth_rate_hz", p.truth_rate_hz);

  const ConfigReader imu = sim.child("imu");
  imu.allowOnly({"rate_hz", "gyro_noise_density", "accel_noise_density", "gyro_bias_random_walk",
                 "accel_bias_random_walk", "gyro_bias_initial_max", "accel_bias_initial_max", "gyro_range",
                 "accel_range"});
  imu.read("rate_hz", p.imu.rate_hz);
  imu.read("gyro_noise_density", p.imu.gyro_noise_density);
  imu.read("accel_noise_density", p.imu.accel_noise_density);
  imu.read("gyro_bias_random_walk", p.imu.gyro_bias_random_walk);
  imu.read("accel_bias_random_walk", p.imu.accel_bias_random_walk);
  imu.read("gyro_bias_initial_max", p.imu.gyro_bias_initial_max);
  imu.read("accel_bias_initial_max", p.imu.accel_bias_initial_max);
  imu.read("gyro_range", p.imu.gyro_range);
  imu.read("accel_range", p.imu.accel_range);

  const ConfigReader vio = sim.child("vio");
  vio.allowOnly({"rate_hz", "latency_min_s", "latency_max_s", "position_std", "attitude_std"});
  vio.read("rate_hz", p.vio.rate_hz);
  vio.read("latency_min_s", p.vio.latency_min_s);
  vio.read("latency_max_s", p.vio.latency_max_s);
  vio.read("position_std", p.vio.position_std);
  vio.read("attitude_std", p.vio.attitude_std);

  const ConfigReader battery = sim.child("battery");
  battery.allowOnly({"enabled", "cell_count", "capacity_mah", "internal_resistance", "initial_charge",
                     "calibration_charge", "idle_power", "rotor_power_coefficient", "thrust_voltage_exponent"});
  battery.read("enabled", p.battery.enabled);
  battery.read("cell_count", p.battery.cell_count);
  battery.read("capacity_mah", p.battery.capacity_mah);
  battery.read("internal_resistance", p.battery.internal_resistance);
  battery.read("initial_charge", p.battery.initial_charge);
  battery.read("calibration_charge", p.battery.calibration_charge);
  battery.read("idle_power", p.battery.idle_power);
  battery.read("rotor_power_coefficient", p.battery.rotor_power_coefficient);
  battery.read("thrust_voltage_exponent", p.battery.thrust_voltage_exponent);

  const ConfigReader ground = sim.child("ground");
  ground.allowOnly({"crash_speed", "crash_tilt"});
  ground.read("crash_speed", p.ground.crash_speed);
  ground.read("crash_tilt", p.ground.crash_tilt);

  const ConfigReader disturbance = sim.child("disturbance");
  disturbance.allowOnly({"max_force", "max_torque", "max_duration", "max_stiffness", "max_damping"});
  disturbance.read("max_force", p.disturbance.max_force);
  disturbance.read("max_torque", p.disturbance.max_torque);
  disturbance.read("max_duration", p.disturbance.max_duration);
  disturbance.read("max_stiffness", p.disturbance.max_stiffness);
  disturbance.read("max_damping", p.disturbance.max_damping);

  sim.read("initial_position", p.initial_position);
  sim.read("initial_yaw", p.initial_yaw);
  int seed = static_cast<int>(p.seed);
  sim.read("seed", seed);
  p.seed = seed;
  sim.read("gravity", p.gravity);

  const std::string reason = p.invalidReason();
  if (!reason.empty()) {
    const auto colon = reason.find(':');
    throw ConfigError(sim.keyPath(reason.substr(0, colon)), reason.substr(colon + 2));
  }
  return p;
}

std::string SimParams::invalidReason() const {
  if (physics_rate_hz < 1000 || physics_rate_hz > 100000 || 1000000 % physics_rate_hz != 0) {
    return "physics_rate_hz: must be in [1000, 100000] with a whole-microsecond period";
  }
  if (truth_rate_hz <= 0 || physics_rate_hz % truth_rate_hz != 0) return "truth_rate_hz: must divide physics_rate_hz";
  if (std::string why = imuInvalidReason(imu, physics_rate_hz); !why.empty()) return why;
  if (std::string why = vioInvalidReason(vio, physics_rate_hz); !why.empty()) return why;
  if (std::string why = batteryInvalidReason(battery); !why.empty()) return why;
  if (!finiteAbove(ground.crash_speed, 0.0)) return "ground.crash_speed: must be > 0";
  if (!(finiteAbove(ground.crash_tilt, 0.0) && ground.crash_tilt <= M_PI)) return "ground.crash_tilt: must be in (0, pi]";
  if (std::string why = disturbanceInvalidReason(disturbance); !why.empty()) return why;
  if (!initial_position.allFinite() || initial_position.z() < 0.0) {
    return "initial_position: must be finite with z >= 0 (the ground is z = 0)";
  }
  if (!std::isfinite(initial_yaw)) return "initial_yaw: must be finite";
  if (seed < 0) return "seed: must be >= 0";
  if (!(finiteAbove(gravity, 0.0) && gravity < 100.0)) return "gravity: must be in (0, 100) m/s^2";
  return {};
}

}  // namespace sdlqr::sim
