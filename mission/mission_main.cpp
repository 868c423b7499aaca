// sdlqr-mission: binds the bus to the mission's core (mission/mission_core.hpp); SIM_CLOCK's
// utime is the clock (100 Hz: the scenario's events are given to the centisecond).

#include <cstdio>
#include <iostream>

#include "sdlqr/bus/core_binding.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/mission/mission_cli.hpp"
#include "sdlqr/mission/mission_core.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  return runMain("sdlqr-mission", [&] {
    ProcessOptions options;
    mission::MissionOptions mission_options;
    bool describe_only = false;
    std::vector<std::string> positional;
    ArgParser parser("sdlqr-mission",
                     "Scenario player: publishes COMMAND, TRAJECTORY, DISTURBANCE and PARAMS at the times of a\n"
                     "scenario file, using SIM_CLOCK's utime as the clock. Exits 0 when the scenario's duration\n"
                     "of simulation time has passed.");
    addProcessOptions(parser, &options);
    mission::addMissionOptions(parser, &mission_options, &describe_only, &positional);
    parser.parseOrExit(argc, argv);
    const mission::Scenario scenario = mission::loadScenarioArgument(positional);
    const std::string vehicle_path = options.config_path.empty() ? scenario.vehicle_path : options.config_path;
    const ConfigReader vehicle = loadVehicleConfig(vehicle_path);
    const auto trajectory_params = trajectory::TrajectoryParams::load(vehicle.child("trajectory"));
    const LqrParams lqr = LqrParams::loadWithVehicle(vehicle);  // with the model's rotor drag, as the controller
    // The controller's guard and transitions: what every trajectory is checked against besides lqr.
    const ConfigReader controller = vehicle.child("controller");
    const mission::PathLimits limits{
        lqr, trajectory::TrajectoryGuardParams::declaration().load(controller.child("guard")),
        trajectory::TransitionParams::declaration().load(controller.child("transition"))};
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-mission", vehicle_path,
                         {printedSection("lqr", lqr), printedSection("trajectory", trajectory_params),
                          printedSection("controller.guard", limits.guard),
                          printedSection("controller.transition", limits.transition)});
      return 0;
    }
    mission::MissionCore core(scenario, trajectory_params, limits, mission_options);
    if (describe_only) return mission::printDescription(scenario, vehicle_path);

    bus::Node node("sdlqr-mission", options, core.health());
    bus::CoreBinding<mission::MissionCore> bus(node, core);  // its ports: MissionCore::inputs()
    core.setObserver(&mission::logEventToStderr);
    core.setThrowObserver(&mission::logThrowToStderr);
    std::fprintf(stderr, "sdlqr-mission: scenario '%s', %zu events, %.1f s\n", scenario.name.c_str(),
                 scenario.events.size(), scenario.duration);
    while (node.spin(20) && !core.finished() && !core.clockLost()) core.onWallTime(bus::monotonicSeconds());
    if (core.clockLost()) std::fprintf(stderr, "sdlqr-mission: no SIM_CLOCK for %.0f s: is sdlqr-sim running on this bus?\n",
                                       mission_options.no_clock_timeout_s);
    else std::fprintf(stderr, "sdlqr-mission: %s at t=%.3f s\n", core.finished() ? "scenario complete" : "stopped",
                      1e-6 * static_cast<double>(core.now()));
    node.shutdown();
    return core.clockLost() ? 1 : 0;
  });
}
