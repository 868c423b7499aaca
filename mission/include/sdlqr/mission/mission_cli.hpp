#pragma once
// The command line of sdlqr-mission, kept out of main so that main only binds the bus.

#include <string>
#include <vector>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/mission/mission_core.hpp"
#include "sdlqr/mission/scenario.hpp"

namespace sdlqr::mission {

// --no-clock-timeout, --resend-interval, --describe and the SCENARIO.yaml argument.
void addMissionOptions(ArgParser& parser, MissionOptions* options, bool* describe_only,
                       std::vector<std::string>* positional);
// Loads the one scenario file (std::invalid_argument / ConfigError).
Scenario loadScenarioArgument(const std::vector<std::string>& positional);
// --describe: name, vehicle, seed, rate, duration and events as key=value lines; returns 0.
int printDescription(const Scenario& scenario, const std::string& vehicle_path);

}  // namespace sdlqr::mission
