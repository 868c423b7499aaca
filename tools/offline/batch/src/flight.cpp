#include "sdlqr/batch/flight.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "sdlqr/analysis/criteria.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/tables/csv.hpp"

namespace sdlqr::batch {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

const std::vector<Metric>& flightMetrics() {
  using R = analysis::FlightReport;
  static const std::vector<Metric> metrics = {
      {"max_tilt_deg", "deg", [](const R& r) { return r.max_tilt_deg; }},
      {"touchdown_speed", "m/s", [](const R& r) { return r.touchdown_speed; }},
      {"jump_settle_time_max", "s",
       [](const R& r) {
         std::vector<analysis::SetpointWindow> jumps;
         std::copy_if(r.setpoints.begin(), r.setpoints.end(), std::back_inserter(jumps),
                      [](const analysis::SetpointWindow& w) { return w.is_jump; });
         return largestOf(jumps, [](const analysis::SetpointWindow& w) { return w.settle_time; });
       }},
      {"hover_error_max", "m",
       [](const R& r) { return largestOf(r.setpoints, [](const analysis::SetpointWindow& w) { return w.steady_error; }); }},
      {"pull_deviation_max", "m",
       [](const R& r) { return largestOf(r.pulls, [](const analysis::PullWindow& w) { return w.max_deviation; }); }},
      {"path_error_rms_max", "m",
       [](const R& r) {
         return largestOf(r.trajectories, [](const analysis::PathTrackingReport& t) { return t.path_error_rms; });
       }},
      {"estimator_position_rms", "m", [](const R& r) { return r.estimator.position_rms_all; }},
      {"estimator_attitude_rms_deg", "deg", [](const R& r) { return r.estimator.attitude_rms_deg_all; }},
  };
  return metrics;
}

BatchContext BatchContext::load(const std::string& spec_path) { return forSpec(BatchSpec::load(spec_path)); }

BatchContext BatchContext::forSpec(BatchSpec spec) {
  BatchContext c{std::move(spec), {}, {}, {}};
  c.scenario = mission::Scenario::load(c.spec.scenario_path);
  analysis::checkCriteriaKeys(c.scenario);
  c.config = closedloop::StackConfig::load(c.scenario.vehicle_path);
  for (const analysis::CriterionSpec& spec : analysis::criteria()) {
    const bool named = c.scenario.criteria.count(std::string(spec.key)) > 0;
    if ((spec.always || named) && !spec.needs_heartbeats && !spec.needs_calibration) c.criteria.emplace_back(spec.key);
  }
  return c;
}

std::vector<std::string> header(const BatchContext& context) {
  std::vector<std::string> h = {"flight", "controller", "seed"};
  for (const ParameterSpec& p : context.spec.parameters) h.push_back(p.parameter.key);
  h.push_back("pass");
  h.push_back("failed_checks");
  for (const std::string& key : context.criteria) h.push_back(key);
  for (const std::string& key : context.criteria) h.push_back(key + ".value");
  for (const Metric& m : flightMetrics()) h.push_back(m.name);
  return h;
}

FlightWorld worldOf(const BatchContext& context, const FlightDraw& draw) {
  std::vector<PlantParameter> parameters;
  for (const ParameterSpec& p : context.spec.parameters) parameters.push_back(p.parameter);
  try {
    FlightWorld world = perturbedWorld(context.config, context.scenario, parameters, draw.values);
    world.scenario.seed = draw.seed;
    return world;
  } catch (const ConfigError& e) {
    throw ConfigError("flight " + std::to_string(draw.flight) + ": " + e.key(),
                      std::string(e.what()).substr(e.key().size() + 2));
  }
}

closedloop::StackConfig stackFlying(const BatchContext& context, const std::string& controller) {
  closedloop::StackConfig config = context.config;
  if (!parseControlLaw(controller, config.lqr.law)) {
    throw ConfigError("controllers", "unknown controller '" + controller + "' (known: " + controlLawNames() + ")");
  }
  return config;
}

FlownFlight fly(const BatchContext& context, const FlightWorld& world, const std::string& controller,
                bool record_motor_commands, logger::FlightLog storage) {
  const closedloop::StackConfig config = stackFlying(context, controller);
  // MOTOR_CMD (1 kHz) is kept only when asked or for the criterion that judges it: rotors at the
  // mixer's limits.
  closedloop::RecordOptions record;
  record.motor_command = record_motor_commands || world.scenario.criteria.count("rotor_at_limit_max") > 0;
  closedloop::ClosedLoop loop(config, world.plant, world.scenario, record);
  loop.recordInto(std::move(storage));
  loop.run();
  FlownFlight flown{world, loop.takeLog(), {}};
  // The limits the stack flies with (the controller's thrust, the mixer's rotors), not the plant's.
  analysis::AnalysisOptions options;
  analysis::setVehicleLimits(options, config.lqr, config.vehicle);
  flown.report = analysis::analyzeFlight(flown.log, world.scenario, options);
  return flown;
}

std::string row(const BatchContext& context, const FlightDraw& draw, const std::string& controller,
                const analysis::FlightReport& report) {
  std::ostringstream text;
  tables::CsvWriter csv(text);
  csv.integer(draw.flight);
  csv.name(controller);
  csv.integer(draw.seed);
  for (double v : draw.values) csv.real(v);
  csv.integer(report.passed() ? 1 : 0);
  csv.integer(std::count_if(report.checks.begin(), report.checks.end(), [](const analysis::Check& c) { return !c.pass; }));
  std::vector<double> worst;
  for (const std::string& key : context.criteria) {
    int judged = 0, passed = 0;
    double value = kNaN;
    for (const analysis::Check& c : report.checks) {
      if (c.key != key) continue;
      ++judged;
      passed += c.pass ? 1 : 0;
      // The worst window: a value never reached (NaN) is worse than any number.
      if (judged == 1 || std::isnan(c.value) || (!std::isnan(value) && (c.upper ? c.value > value : c.value < value))) {
        value = c.value;
      }
    }
    if (judged == 0) {
      csv.name("");
    } else {
      csv.integer(passed == judged ? 1 : 0);
    }
    worst.push_back(judged == 0 ? kNaN : value);
  }
  for (double v : worst) csv.real(v);
  for (const Metric& m : flightMetrics()) csv.real(m.of(report));
  csv.endRow();
  return text.str();
}

namespace {

std::string absolute(const std::string& path) {
  if (!path.empty() && path[0] == '/') return path;
  char* real = ::realpath(path.c_str(), nullptr);
  const std::string out = real ? real : path;
  std::free(real);
  return out;
}

void scaleList(YAML::Node list, double scale) {
  for (size_t i = 0; i < list.size(); ++i) list[i] = yamlNumber(list[i].as<double>() * scale);
}

void writeFile(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  if (!out.flush()) throw std::runtime_error(path + ": cannot write");
}

}  // namespace

void writeFlightFiles(const BatchContext& context, const FlightDraw& draw, const std::string& controller,
                      const std::string& dir) {
  const FlightWorld world = worldOf(context, draw);
  YAML::Node vehicle = YAML::Clone(loadYamlFile(context.scenario.vehicle_path));
  vehicle["lqr"]["law"] = toString(stackFlying(context, controller).lqr.law);
  YAML::Emitter vehicle_text;
  vehicle_text << vehicle;
  writeFile(dir + "/vehicle.yaml", "# " + absolute(context.scenario.vehicle_path) + " flying " + controller +
                                       " (sdlqr-batch --refly)\n" + vehicle_text.c_str() + "\n");
  // The scenario file with the flown events: the disturbances the draw scaled and delayed.
  ScenarioPerturbation perturbation;
  for (size_t i = 0; i < context.spec.parameters.size(); ++i) {
    const PlantParameter& p = context.spec.parameters[i].parameter;
    if (p.target != Target::kScenario) continue;
    if (p.section_key == "disturbance_scale") perturbation.disturbance_scale = draw.values[i];
    if (p.section_key == "disturbance_delay") perturbation.disturbance_delay = draw.values[i];
  }
  YAML::Node scenario = YAML::Clone(loadYamlFile(context.spec.scenario_path));
  scenario["vehicle"] = absolute(dir + "/vehicle.yaml");
  const bool stressed = std::any_of(context.spec.parameters.begin(), context.spec.parameters.end(),
                                    [](const ParameterSpec& p) { return p.parameter.target == Target::kStress; });
  if (stressed) scenario["sim"] = stressNode(world.scenario.sim);
  scenario["seed"] = std::to_string(draw.seed);
  for (YAML::Node event : scenario["events"]) {
    if (event["trajectory"] && event["trajectory"]["csv"]) {
      event["trajectory"]["csv"] = absolute(context.scenario.path.substr(0, context.scenario.path.find_last_of('/') + 1) +
                                            event["trajectory"]["csv"].Scalar());
    }
    if (!event["disturbance"]) continue;
    event["at"] = yamlNumber(std::max(0.0, event["at"].as<double>() + perturbation.disturbance_delay));
    if (event["disturbance"]["force"]) scaleList(event["disturbance"]["force"], perturbation.disturbance_scale);
    if (event["disturbance"]["torque"]) scaleList(event["disturbance"]["torque"], perturbation.disturbance_scale);
  }
  YAML::Emitter emitted;
  emitted << scenario;
  writeFile(dir + "/scenario.yaml", "# flight " + std::to_string(draw.flight) + " of batch " + context.spec.path +
                                        " (sdlqr-batch --refly)\n" + emitted.c_str() + "\n");
  std::ostringstream plant;
  printSections(plant, {"the simulator's plant of flight " + std::to_string(draw.flight) + " of " + context.spec.path,
                        "(sdlqr-sim --config this file; every other process keeps the scenario's vehicle file)"},
                {printedSection("vehicle", world.plant.vehicle), printedSection("sim", world.plant.sim)});
  writeFile(dir + "/plant.yaml", plant.str());
}

FlightWorld loadFlightFiles(const std::string& dir) {
  const closedloop::StackConfig plant = closedloop::StackConfig::load(dir + "/plant.yaml");
  return {{plant.vehicle, plant.sim}, mission::Scenario::load(dir + "/scenario.yaml")};
}

}  // namespace sdlqr::batch
