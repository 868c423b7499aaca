// sdlqr-estimator: binds the bus to the estimator's core (estimator/estimator_core.hpp).

#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/estimator/estimator_core.hpp"

using namespace sdlqr;
using estimator::EstimatorCore;

int main(int argc, char** argv) {
  const ProcessOptions options = parseProcessCommandLine(argc, argv, "sdlqr-estimator",
      "Error-state EKF: fuses IMU with delayed VIO poses at their capture time and publishes\n"
      "STATE_EST at the configured rate (default 250 Hz) on the IMU-time grid. Reads the\n"
      "`estimator:` section of the vehicle file. Never reads SIM_TRUTH.\n"
      "In: IMU, VIO_POSE.  Out: STATE_EST, HEARTBEAT (with the vehicle prefix if given).");
  return runMain("sdlqr-estimator", [&]() {
    estimator::EstimatorParams params;
    // The vehicle file's reader: an unknown section is an error here as in every process.
    if (!options.config_path.empty()) params = estimator::EstimatorParams::load(loadVehicleConfig(options.config_path).child("estimator"));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-estimator", options.config_path, {printedSection("estimator", params)});
      return 0;
    }
    EstimatorCore core(params);
    bus::Node node("sdlqr-estimator", options, core.health());
    bus::CoreBinding<EstimatorCore> bus(node, core);  // its ports: EstimatorCore::inputs()
    bus.serve(100);
    return 0;
  });
}
