#pragma once
// One flight of a batch on the in-process closed loop (the process cores the executables run),
// judged by the scenario's criteria (tools/examine/analysis/src/criteria.cpp), as one CSV row:
//
//   flight, controller, seed, <each parameter>, pass, failed_checks,
//   <each criterion judged in-process> (1 pass, 0 fail, empty: no window to judge),
//   <criterion>.value (the worst window's value), <each metric of flightMetrics()>
//
// Numbers print so they read back bit for bit (logger/csv.hpp), and nothing depends on the machine
// or the clock: the same draw gives the same row on every thread, shard and host.

#include <string>
#include <vector>

#include "sdlqr/analysis/flight_report.hpp"
#include "sdlqr/batch/draws.hpp"
#include "sdlqr/batch/metric.hpp"

namespace sdlqr::batch {

// The metrics every row carries besides the criteria (crash and non-finite messages are criteria
// of every flight), declared once.
const std::vector<Metric>& flightMetrics();

// What a batch flies: the nominal stack and scenario, loaded once and shared by every flight.
struct BatchContext {
  BatchSpec spec;
  closedloop::StackConfig config;
  mission::Scenario scenario;
  std::vector<std::string> criteria;  // the criterion keys judged in-process, in table order

  static BatchContext load(const std::string& spec_path);
  // The context of a spec already read (or built by a caller that flies scenarios of its own).
  static BatchContext forSpec(BatchSpec spec);
};

std::vector<std::string> header(const BatchContext& context);

struct FlownFlight {
  FlightWorld world;
  logger::FlightLog log;
  analysis::FlightReport report;
};

// The nominal stack with the controller process running `controller` (a law of lqr.law).
closedloop::StackConfig stackFlying(const BatchContext& context, const std::string& controller);
// Flies one world with one controller; MOTOR_CMD is recorded (and the rotor saturation counted)
// when the scenario judges it or `record_motor_commands` asks for it. The flight is recorded into
// `storage`'s memory: a worker hands back its last flight's log and allocates nothing.
FlownFlight fly(const BatchContext& context, const FlightWorld& world, const std::string& controller,
                bool record_motor_commands = false, logger::FlightLog storage = {});
// The world of a draw (throws ConfigError "flight 17: vehicle.mass: ..." when it is no valid plant).
FlightWorld worldOf(const BatchContext& context, const FlightDraw& draw);
// The CSV row of a flown draw, '\n' included.
std::string row(const BatchContext& context, const FlightDraw& draw, const std::string& controller,
                const analysis::FlightReport& report);

// Files that reproduce one flight away from the batch: scenario.yaml (its events and `sim:`
// stressors as flown, the flight's seed, vehicle.yaml), vehicle.yaml (the nominal vehicle file
// with lqr.law: controller) and plant.yaml (the simulator's vehicle and sim sections).
// `./sdlqr run scenario.yaml --plant-config plant.yaml` flies it over the bus.
void writeFlightFiles(const BatchContext& context, const FlightDraw& draw, const std::string& controller,
                      const std::string& dir);
FlightWorld loadFlightFiles(const std::string& dir);

}  // namespace sdlqr::batch
