// sdlqr-lowlevel: binds the bus to the bodyrate loop's core (lowlevel/lowlevel_core.hpp).

#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/lowlevel/lowlevel_core.hpp"
#include "sdlqr/lowlevel/param_check.hpp"
#include "sdlqr/math/lqr_params.hpp"

using namespace sdlqr;
using lowlevel::LowlevelCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-lowlevel", [&] {
    const ProcessOptions options = parseProcessCommandLine(argc, argv, "sdlqr-lowlevel",
        "Bodyrate loop, one step per IMU sample (1 kHz): rate PID, mixer with desaturation,\n"
        "arming, and the RATE_CMD-silent failsafe (level, descend, disarm on the ground).\n"
        "In: IMU, RATE_CMD, COMMAND, PARAMS (FIELD_MASS).  Out: MOTOR_CMD, HEARTBEAT.");

    const ConfigReader config = loadVehicleConfig(options.config_path);
    const VehicleParams vehicle = VehicleParams::load(config.child("vehicle"));
    const LqrParams lqr = LqrParams::load(config.child("lqr"));
    const lowlevel::LowlevelParams params = lowlevel::LowlevelParams::load(config.child("lowlevel"));
    lowlevel::throwIfInvalid(config.child("lowlevel"), params.invalidReasonFor(vehicle, lqr.gravity));
    const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
    lowlevel::throwIfInvalid(config.child("lowlevel"), params.invalidReasonFor(limits));
    const FaultParams faults = FaultParams::load(config.child("faults"));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-lowlevel", options.config_path,
                         {printedSection("vehicle", vehicle), printedSection("lqr", lqr), printedSection("lowlevel", params),
                          printedSection("faults", faults), printedSection("validation", limits)});
      return 0;
    }
    LowlevelCore core(vehicle, params, lqr.gravity, faults, limits);
    bus::Node node("sdlqr-lowlevel", options, core.health());
    bus::CoreBinding<LowlevelCore> bus(node, core);  // its ports: LowlevelCore::inputs()
    bus.serve(core.wallTimePeriodMs());
    return 0;
  });
}
