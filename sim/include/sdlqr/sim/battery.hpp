#pragma once
// LiPo pack: open-circuit voltage from the state of charge, sag across the internal resistance
// under the rotors' electrical load, and the thrust error this causes. The bodyrate loop's
// thrust model was calibrated at `calibration_charge` in hover, so thrust_scale() is 1 there,
// above 1 on a fuller pack and below 1 on an emptier one or under heavy load (paper §IV-B z offset).

#include "sdlqr/math/types.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/sim/sim_params.hpp"

namespace sdlqr::sim {

// Resting voltage of one LiPo cell at a state of charge in [0, 1] (typical discharge curve).
double lipoCellOpenCircuitVoltage(double charge);

struct BatteryLoad {
  double current = 0.0;          // [A]
  double terminal_voltage = 0.0; // [V]
};

// Current and terminal voltage of a source with open-circuit voltage v_oc and resistance r
// delivering `power`: the smaller root of r I^2 - v_oc I + power = 0. Beyond the source's
// maximum power (v_oc^2 / 4r) it delivers that maximum.
BatteryLoad batteryLoad(double v_oc, double r, double power);

class Battery {
 public:
  // Throws std::invalid_argument when the pack cannot deliver hover power at calibration charge.
  Battery(const BatteryParams& params, const VehicleParams& vehicle, double gravity);

  // Drains the pack for dt seconds at the electrical load of the given rotor thrusts [N].
  void update(double dt, const Vec4& rotor_thrust);

  double charge() const { return charge_; }
  double voltage() const { return load_.terminal_voltage; }
  double current() const { return load_.current; }
  // Produced over commanded thrust.
  double thrustScale() const { return thrust_scale_; }
  double calibrationVoltage() const { return calibration_voltage_; }
  // Electrical power [W] drawn at these rotor thrusts.
  double power(const Vec4& rotor_thrust) const;

 private:
  double openCircuitVoltage() const;

  BatteryParams params_;
  double charge_;
  double calibration_voltage_ = 0.0;
  BatteryLoad load_;
  double thrust_scale_ = 1.0;
};

}  // namespace sdlqr::sim
