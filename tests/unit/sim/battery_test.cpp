// Battery: charge drain, voltage sag, and the thrust error against the 70 % calibration.
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "sdlqr/sim/battery.hpp"
#include "sim_test_support.hpp"

namespace sdlqr::sim {
namespace {

using test::hoverThrust;

TEST(Battery, LoadSolvesPowerBalance) {
  const double v_oc = 11.6, r = 0.1;
  for (const double power : {0.0, 5.0, 40.0, 200.0}) {
    const BatteryLoad load = batteryLoad(v_oc, r, power);
    EXPECT_NEAR(load.terminal_voltage * load.current, power, 1e-9 * (1.0 + power));
    EXPECT_NEAR(load.terminal_voltage, v_oc - r * load.current, 1e-12);
  }
  // Beyond v^2 / 4r the source gives its maximum power at half voltage.
  const BatteryLoad overload = batteryLoad(v_oc, r, 1000.0);
  EXPECT_NEAR(overload.terminal_voltage, v_oc / 2.0, 1e-12);
}

TEST(Battery, CellVoltageRisesWithCharge) {
  EXPECT_DOUBLE_EQ(lipoCellOpenCircuitVoltage(1.0), 4.20);
  EXPECT_DOUBLE_EQ(lipoCellOpenCircuitVoltage(0.0), 3.27);
  for (double c = 0.0; c < 1.0; c += 0.01) {
    EXPECT_LT(lipoCellOpenCircuitVoltage(c), lipoCellOpenCircuitVoltage(c + 0.01)) << "charge " << c;
  }
}

TEST(Battery, VoltageFallsAndThrustScaleCrossesOneAtCalibrationCharge) {
  // GIVEN a pack at 85 % feeding hover thrust
  BatteryParams params;
  params.initial_charge = 0.85;
  const VehicleParams v;
  Battery battery(params, v, kDefaultGravity);
  const Vec4 hover = hoverThrust(v);
  const double dt = 0.001;
  battery.update(dt, hover);
  EXPECT_GT(battery.thrustScale(), 1.0);
  // WHEN it drains until 55 %
  double charge_at_crossing = -1.0;
  double previous_voltage = battery.voltage();
  double charge_used = 0.0;  // [C]
  double seconds = 0.0;
  while (battery.charge() > 0.55) {
    const double scale_before = battery.thrustScale();
    charge_used += battery.current() * dt;
    battery.update(dt, hover);
    seconds += dt;
    // THEN the voltage never rises under a constant load
    ASSERT_LE(battery.voltage(), previous_voltage + 1e-12);
    previous_voltage = battery.voltage();
    if (scale_before >= 1.0 && battery.thrustScale() < 1.0) charge_at_crossing = battery.charge();
  }
  // AND thrust is exact at the calibration charge: more before, less after
  std::cout << "hover at " << battery.current() << " A; thrust_scale crossed 1.0 at charge " << charge_at_crossing
            << " after " << seconds << " s\n";
  EXPECT_NEAR(charge_at_crossing, params.calibration_charge, 1e-3);
  EXPECT_LT(battery.thrustScale(), 1.0);
  // AND the drained charge equals the integrated current (coulomb counting)
  EXPECT_NEAR((0.85 - battery.charge()) * params.capacity_mah * 3.6, charge_used, 1e-3 * charge_used);
}

TEST(Battery, HeavierLoadSagsMoreAndGivesLessThrust) {
  const VehicleParams v;
  Battery light(BatteryParams(), v, kDefaultGravity);
  Battery heavy(BatteryParams(), v, kDefaultGravity);
  light.update(0.001, hoverThrust(v));
  heavy.update(0.001, 2.0 * hoverThrust(v));
  EXPECT_GT(heavy.current(), light.current());
  EXPECT_LT(heavy.voltage(), light.voltage());
  EXPECT_LT(heavy.thrustScale(), light.thrustScale());
}

TEST(Battery, DisabledSupplyKeepsThrustExact) {
  BatteryParams params;
  params.enabled = false;
  params.initial_charge = 1.0;
  Battery battery(params, VehicleParams(), kDefaultGravity);
  battery.update(0.001, Vec4::Constant(1.0));
  EXPECT_EQ(battery.thrustScale(), 1.0);
  EXPECT_GT(battery.voltage(), 0.0);
}

TEST(Battery, SimulatorAppliesTheScaleToRotorThrust) {
  // A full pack: the rotors produce more than the (settled) setpoint, by the reported scale.
  SimParams p;
  p.battery.initial_charge = 1.0;
  const VehicleParams v;
  Simulator sim(v, p);
  sim.setMotorCommand(test::armed(0.8 * hoverThrust(v)));
  test::runFor(sim, 0.5);
  const SimTruth t = sim.truth();
  std::cout << "full pack: " << t.battery_voltage << " V, thrust_scale " << t.thrust_scale << "\n";
  EXPECT_GT(t.thrust_scale, 1.05);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(t.rotor_thrust[i], t.thrust_scale * 0.8 * hoverThrust(v)[i], 1e-3);
}

TEST(Battery, PackThatCannotHoverIsRejected) {
  SimParams p;
  p.battery.internal_resistance = 5.0;
  EXPECT_THROW(Simulator(VehicleParams(), p), std::invalid_argument);
}

}  // namespace
}  // namespace sdlqr::sim
