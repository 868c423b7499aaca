#include "sdlqr/px4emu/emulator_config.hpp"

#include "sdlqr/lowlevel/param_check.hpp"

namespace sdlqr::px4emu {

EmulatorConfig loadEmulatorConfig(const ConfigReader& root) {
  EmulatorConfig c;
  c.vehicle = VehicleParams::load(root.child("vehicle"));
  c.sim = sim::SimParams::load(root.child("sim"));
  c.estimator = estimator::EstimatorParams::load(root.child("estimator"));
  c.lowlevel = lowlevel::LowlevelParams::load(root.child("lowlevel"));
  c.lqr = LqrParams::load(root.child("lqr"));
  c.faults = FaultParams::load(root.child("faults"));
  c.validation = ValidationLimits::load(root.child("validation"));
  c.emulator = EmulatorParams::load(root.child("px4_emulator"));
  lowlevel::throwIfInvalid(root.child("lowlevel"), c.lowlevel.invalidReasonFor(c.vehicle, c.lqr.gravity));
  lowlevel::throwIfInvalid(root.child("lowlevel"), c.lowlevel.invalidReasonFor(c.validation));
  return c;
}

std::vector<PrintedSection> printedSections(const EmulatorConfig& c) {
  return {printedSection("vehicle", c.vehicle),         printedSection("lqr", c.lqr),
          printedSection("sim", c.sim),                 printedSection("estimator", c.estimator),
          printedSection("lowlevel", c.lowlevel),       printedSection("faults", c.faults),
          printedSection("validation", c.validation),   printedSection("px4_emulator", c.emulator)};
}

}  // namespace sdlqr::px4emu
