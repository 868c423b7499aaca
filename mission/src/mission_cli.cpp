#include "sdlqr/mission/mission_cli.hpp"

#include <cstdio>
#include <stdexcept>

namespace sdlqr::mission {

void addMissionOptions(ArgParser& parser, MissionOptions* options, bool* describe_only,
                       std::vector<std::string>* positional) {
  parser.addOption("--no-clock-timeout", &options->no_clock_timeout_s, "S",
                   "give up (exit 1) when no SIM_CLOCK arrives for this many wall seconds (default 10)");
  parser.addOption("--resend-interval", &options->resend_interval_s, "S",
                   "re-send the current command and pull S/10 s of simulation time after they are sent, then\n"
                   "every S s, for a restarted process and a lost datagram (default 1, 0: never)",
                   Range::closed(0, 60));
  parser.addFlag("--describe", describe_only,
                 "validate the scenario, print name, vehicle, seed, rate and duration as key=value lines, exit");
  parser.allowPositional(positional, "SCENARIO.yaml");
}

Scenario loadScenarioArgument(const std::vector<std::string>& positional) {
  if (positional.size() != 1) throw std::invalid_argument("expected one scenario file (see --help)");
  return Scenario::load(positional[0]);
}

int printDescription(const Scenario& scenario, const std::string& vehicle_path) {
  std::printf("name=%s\nvehicle=%s\nseed=%lld\nrate=%.17g\nduration=%.17g\nevents=%zu\n", scenario.name.c_str(),
              vehicle_path.c_str(), scenario.seed, scenario.rate, scenario.duration, scenario.events.size());
  return 0;
}

}  // namespace sdlqr::mission
