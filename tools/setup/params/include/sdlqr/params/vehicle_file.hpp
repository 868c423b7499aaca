#pragma once
// The vehicle file as a whole: every section with the struct that declares it. config/quad255.yaml
// is defaultVehicleFileText(), printed from the declarations (a unit test keeps the two equal);
// `sdlqr-params` prints it, checks a file, and shows a file's values.

#include <string>
#include <utility>
#include <vector>

#include "sdlqr/config/print_config.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/lowlevel/lowlevel_params.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/px4/bridge_params.hpp"
#include "sdlqr/px4emu/emulator_params.hpp"
#include "sdlqr/sim/sim_params.hpp"
#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::params {

// Every section of a vehicle file, loaded.
struct VehicleFile {
  VehicleParams vehicle;
  LqrParams lqr;
  sim::SimParams sim;
  estimator::EstimatorParams estimator;
  controller::ControllerParams controller;
  gains::GainsParams gains;
  lowlevel::LowlevelParams lowlevel;
  trajectory::TrajectoryParams trajectory;
  FaultParams faults;
  ValidationLimits validation;
  px4::BridgeParams px4;
  px4emu::EmulatorParams px4_emulator;

  // Every section of `path` (empty: the defaults) and the rules across sections (the lowlevel
  // against the airframe and the validation limits); throws ConfigError naming the key.
  static VehicleFile load(const std::string& path);
  // Each section with its values, in file order.
  std::vector<PrintedSection> sections() const;
};

// Calls visit(name, section) for each section of `file` in file order: the one list of sections.
template <class File, class Visit>
void forEachSection(File& file, Visit&& visit) {
  visit("vehicle", file.vehicle);
  visit("lqr", file.lqr);
  visit("sim", file.sim);
  visit("estimator", file.estimator);
  visit("controller", file.controller);
  visit("gains", file.gains);
  visit("lowlevel", file.lowlevel);
  visit("trajectory", file.trajectory);
  visit("faults", file.faults);
  visit("validation", file.validation);
  visit("px4", file.px4);
  visit("px4_emulator", file.px4_emulator);
}

// Each section's name and declaration, in file order.
std::vector<std::pair<std::string, const ParamSection*>> declarations();

// The vehicle file of defaults, with its header: the text of config/quad255.yaml.
std::string defaultVehicleFileText();

// Empty when `expected` and `actual` are the same text, else where they first differ:
// "line 12: expected '  mass: 0.255 ...', found '  mass: 0.3 ...'".
std::string firstDifference(const std::string& expected, const std::string& actual);

}  // namespace sdlqr::params
