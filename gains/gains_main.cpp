// sdlqr-gains: the state-dependent LQR gain solver. Bus mode (default): binds the bus to the gain
// solver's core (gains/gains_core.hpp), which solves at 10 Hz of simulation time and publishes
// GAINS. One-shot mode (--once): solve at the given point and print one JSON object.

#include <iostream>
#include <stdexcept>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/gains/gains_cli.hpp"
#include "sdlqr/gains/gains_core.hpp"

using namespace sdlqr;
using gains::GainsCore;

int main(int argc, char** argv) {
  return runMain("sdlqr-gains", [&] {
    gains::OnceOptions once;
    ProcessOptions options;
    ArgParser parser("sdlqr-gains", "State-dependent LQR gain solver (paper §II-C, II-D).");
    gains::addOnceOptions(parser, &once);
    addProcessOptions(parser, &options);
    parser.setEpilog(gains::kOnceEpilog);
    parser.parseOrExit(argc, argv);
    const ConfigReader config = loadVehicleConfig(options.config_path);
    const LqrParams lqr = gains::lqrParamsWithMethod(config, once);
    if (once.once && options.print_config) {
      printProcessConfig(std::cout, "sdlqr-gains --once", options.config_path, {printedSection("lqr", lqr)});
      return 0;
    }
    if (once.once) return gains::solveOnce(once, lqr, std::cout);
    gains::requireBusMode(once);

    const gains::GainsParams params = gains::GainsParams::load(config.child("gains"));
    const FaultParams faults = FaultParams::load(config.child("faults"));
    const ValidationLimits limits = ValidationLimits::load(config.child("validation"));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-gains", options.config_path,
                         {printedSection("lqr", lqr), printedSection("gains", params), printedSection("faults", faults),
                          printedSection("validation", limits)});
      return 0;
    }
    GainsCore core(lqr, params, faults, limits, &bus::monotonicSeconds);
    bus::Node node("sdlqr-gains", options, core.health());
    bus::CoreBinding<GainsCore> bus(node, core);  // its ports: GainsCore::inputs()
    std::cerr << "sdlqr-gains: solving at " << params.rate_hz << " Hz on " << node.channel(channel::kStateEstimate) << " (" << toString(lqr.method)
              << " method)\n";
    bus.serve(20);
    return 0;
  });
}
