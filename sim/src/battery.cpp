#include "sdlqr/sim/battery.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "sdlqr/math/same_bits.hpp"

namespace sdlqr::sim {

double lipoCellOpenCircuitVoltage(double charge) {
  // [V] at charge 0, 0.1, ..., 1.0: steep at both ends, a flat plateau between.
  static constexpr std::array<double, 11> kVoltage = {3.27, 3.69, 3.71, 3.73, 3.77, 3.79,
                                                      3.82, 3.87, 3.93, 4.03, 4.20};
  const double x = std::clamp(charge, 0.0, 1.0) * 10.0;
  const int i = std::min(static_cast<int>(x), 9);
  const double f = x - i;
  return kVoltage[static_cast<size_t>(i)] * (1.0 - f) + kVoltage[static_cast<size_t>(i) + 1] * f;
}

BatteryLoad batteryLoad(double v_oc, double r, double power) {
  BatteryLoad load;
  if (r <= 0.0) {
    load.current = power / v_oc;
    load.terminal_voltage = v_oc;
    return load;
  }
  const double discriminant = v_oc * v_oc - 4.0 * r * power;
  if (discriminant <= 0.0) {
    load.current = v_oc / (2.0 * r);
  } else {
    // Written as 2P / (v + sqrt(d)) so small loads do not cancel catastrophically.
    load.current = 2.0 * power / (v_oc + std::sqrt(discriminant));
  }
  load.terminal_voltage = v_oc - r * load.current;
  return load;
}

Battery::Battery(const BatteryParams& params, const VehicleParams& vehicle, double gravity)
    : params_(params), charge_(params.initial_charge) {
  const double hover_power = power(Vec4::Constant(vehicle.hoverThrustPerRotor(gravity)));
  const double v_oc_calibration = params_.cell_count * lipoCellOpenCircuitVoltage(params_.calibration_charge);
  if (4.0 * params_.internal_resistance * hover_power >= v_oc_calibration * v_oc_calibration) {
    throw std::invalid_argument("sim.battery: the pack cannot deliver hover power at calibration_charge");
  }
  calibration_voltage_ = batteryLoad(v_oc_calibration, params_.internal_resistance, hover_power).terminal_voltage;
  update(0.0, Vec4::Zero());
}

double Battery::power(const Vec4& rotor_thrust) const {
  Vec4 thrust;
  for (int i = 0; i < 4; ++i) thrust[i] = std::max(rotor_thrust[i], 0.0);
  // Momentum theory: induced power ~ T^1.5 (vector square roots, summed in rotor order).
  const Vec4 induced = thrust.cwiseProduct(thrust.cwiseSqrt());
  double rotors = 0.0;
  for (int i = 0; i < 4; ++i) rotors += induced[i];
  return params_.idle_power + params_.rotor_power_coefficient * rotors;
}

double Battery::openCircuitVoltage() const { return params_.cell_count * lipoCellOpenCircuitVoltage(charge_); }

void Battery::update(double dt, const Vec4& rotor_thrust) {
  load_ = batteryLoad(openCircuitVoltage(), params_.internal_resistance, power(rotor_thrust));
  const double capacity_coulomb = params_.capacity_mah * 3.6;
  charge_ = std::max(0.0, charge_ - load_.current * dt / capacity_coulomb);
  thrust_scale_ = params_.enabled
                      ? powSameBits(load_.terminal_voltage / calibration_voltage_, params_.thrust_voltage_exponent)
                      : 1.0;
}

}  // namespace sdlqr::sim
