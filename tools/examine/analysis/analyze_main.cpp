// sdlqr-analyze: scenario metrics and pass/fail checks of a recorded flight.

#include <fstream>
#include <iostream>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/calibrate/calibration.hpp"
#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/config.hpp"
#include "sdlqr/math/lqr_params.hpp"

using namespace sdlqr;

int main(int argc, char** argv) {
  return runMain("sdlqr-analyze", [&] {
    std::string scenario_path, vehicle, json_path, summary_path, calibration_path;
    std::vector<std::string> positional;
    ArgParser parser("sdlqr-analyze",
                     "Computes the scenario metrics of a flight log (settling after each reference jump,\n"
                     "recovery after each pull, estimator accuracy, rates, solver and loop timing) and checks\n"
                     "every criterion of the scenario file.");
    parser.addOption("--scenario", &scenario_path, "FILE", "scenario file the flight was flown with", Presence::kRequired);
    parser.addOption("--vehicle", &vehicle, "PREFIX", "channel prefix of the vehicle to analyse");
    parser.addOption("--json", &json_path, "FILE", "write the full report as JSON");
    parser.addOption("--summary", &summary_path, "FILE", "also write the printed summary to FILE");
    parser.addOption("--calibration", &calibration_path, "FILE",
                     "this machine's bus measured before the flight (sdlqr-calibrate --out FILE): needed by\n"
                     "the relative budgets (stack_cpu_relative_max, state_to_command_latency_relative_max, rate_cmd_wall_jitter_relative_max)");
    parser.allowPositional(&positional, "LOG.lcmlog");
    parser.setEpilog("exit codes: 0 every check passes, 1 a check fails, 2 bad arguments or unreadable files");
    parser.parseOrExit(argc, argv);
    if (positional.size() != 1) throw std::invalid_argument("expected one log file (see --help)");

    const mission::Scenario scenario = mission::Scenario::load(scenario_path);
    logger::FlightLog log;
    try {
      log = logger::FlightLog::load(positional[0], vehicle);
    } catch (const std::exception& e) {
      throw std::invalid_argument(e.what());
    }
    // The saturation criteria's limits come from the scenario's vehicle file (analyzeFlight).
    analysis::AnalysisOptions options;
    if (!calibration_path.empty()) options.calibration = calibrate::Calibration::load(calibration_path);
    const analysis::FlightReport report = analysis::analyzeFlight(log, scenario, options);
    analysis::writeSummary(report, std::cout);
    if (!summary_path.empty()) {
      std::ofstream out(summary_path);
      if (!out) throw std::invalid_argument("cannot write " + summary_path);
      analysis::writeSummary(report, out);
    }
    if (!json_path.empty()) {
      std::ofstream out(json_path);
      if (!out) throw std::invalid_argument("cannot write " + json_path);
      analysis::writeJson(report, out);
    }
    return report.passed() ? 0 : 1;
  });
}
