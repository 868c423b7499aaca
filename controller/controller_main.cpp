// sdlqr-controller: binds the bus to the controller's core (controller/controller_core.hpp).

#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/controller/controller_core.hpp"

using namespace sdlqr;
using controller::ControllerCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-controller", [&] {
    const ProcessOptions options = parseProcessCommandLine(argc, argv, "sdlqr-controller",
        "State-dependent LQR at 100 Hz of simulation time: u = u0 + K (x - x0) with the newest\n"
        "GAINS, the paper's input limits and a setpoint or trajectory reference.\n"
        "In: STATE_EST, GAINS, TRAJECTORY, PARAMS, COMMAND.  Out: RATE_CMD, REFERENCE, HEARTBEAT.");

    const ConfigReader config = loadVehicleConfig(options.config_path);
    const LqrParams lqr = LqrParams::loadWithVehicle(config);
    const auto params = controller::ControllerParams::load(config.child("controller"));
    const FaultParams faults = FaultParams::load(config.child("faults"));
    const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
    throwIfInvalid(config.child("lqr"), lqrLimitsInvalidReason(lqr, limits));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-controller", options.config_path,
                         {printedSection("lqr", lqr), printedSection("controller", params),
                          printedSection("faults", faults), printedSection("validation", limits)});
      return 0;
    }
    ControllerCore core(lqr, params, faults, limits);
    bus::Node node("sdlqr-controller", options, core.health());
    bus::CoreBinding<ControllerCore> bus(node, core);  // its ports: ControllerCore::inputs()
    std::cerr << "sdlqr-controller: running on " << node.channel(channel::kStateEstimate) << "\n";
    bus.serve(core.wallTimePeriodMs());  // short spins: the watchdog notices a silent estimator in time
    return 0;
  });
}
