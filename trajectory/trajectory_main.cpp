// sdlqr-trajectory: generate the paper's reference trajectories (or min-snap through your
// waypoints), write them as CSV and print their feasibility against the LQR limits.
// Not a bus process: the scenario player uploads the CSV it writes.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/feasibility.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/params.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"
#include "sdlqr/trajectory/waypoint_file.hpp"

namespace {

using namespace sdlqr;
using namespace sdlqr::trajectory;

constexpr int kExitInfeasible = 3;

bool endsWith(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

struct Options {
  std::string config_path;
  std::string output_path;
  std::string check_path;
  double v_max = std::numeric_limits<double>::quiet_NaN();  // NaN: not given (the parser rejects NaN input)
  double dt = std::numeric_limits<double>::quiet_NaN();
  bool periodic = false;
  bool temporal = false;
  bool require_feasible = false;
  bool print_config = false;
  std::vector<std::string> sources;
};

Options parseOptions(int argc, const char* const* argv) {
  Options o;
  ArgParser parser("sdlqr-trajectory",
                   "Generates a reference trajectory, writes it as CSV and reports its feasibility against the\n"
                   "LQR limits (c_min, c_max, omega_max of the lqr section) and v_max.\n"
                   "SOURCE is minsnap_fast (paper III-C.2), minsnap_slow (III-C.4), ellipse (III-C.3, infeasible\n"
                   "by design) or a waypoint file (.yaml/.yml or .csv, see trajectory/README.md).");
  parser.addOption("--config", &o.config_path, "FILE", "vehicle file: lqr limits and the trajectory section");
  parser.addOption("--output", &o.output_path, "FILE", "write the sampled trajectory as CSV ('-': stdout)");
  parser.addOption("--check", &o.check_path, "FILE", "validate a trajectory CSV and report its feasibility");
  parser.addOption("--v-max", &o.v_max, "M_PER_S", "top speed for a waypoint file (overrides its v_max)", Range::above(0));
  parser.addOption("--dt", &o.dt, "SECONDS", "sample spacing (default trajectory.sample_dt, 0.1 s)", Range::above(0));
  parser.addFlag("--periodic", &o.periodic, "min-snap: one closed periodic lap instead of rest to rest");
  parser.addFlag("--temporal", &o.temporal, "mark the trajectory for temporal tracking (default spatial)");
  parser.addFlag("--require-feasible", &o.require_feasible, "exit 3 when a limit is violated");
  parser.addFlag("--print-config", &o.print_config,
                 "print the lqr and trajectory sections as they would be used (defaults, --config,\n"
                 "                          --periodic, --dt), as YAML, and exit");
  parser.allowPositional(&o.sources, "[SOURCE]");
  parser.setEpilog(
      "examples:\n"
      "  sdlqr-trajectory minsnap_fast --output fast.csv\n"
      "  sdlqr-trajectory waypoints.yaml --v-max 2 --output mine.csv\n"
      "  sdlqr-trajectory --check mine.csv --require-feasible\n"
      "exit codes: 0 done, 2 bad input or configuration, 3 infeasible with --require-feasible");
  parser.parseOrExit(argc, argv);
  if (!o.print_config && o.sources.size() + (o.check_path.empty() ? 0 : 1) != 1) {
    throw std::invalid_argument("give exactly one SOURCE or --check FILE (see --help)");
  }
  return o;
}

// The lqr and trajectory sections: defaults, then --config, then --periodic and --dt.
struct Sections {
  LqrParams lqr;
  TrajectoryParams params;
};

Sections loadSections(const Options& o) {
  Sections s;
  if (!o.config_path.empty()) {
    const ConfigReader root = loadVehicleConfig(o.config_path);
    s.lqr = LqrParams::loadWithVehicle(root);  // the model's rotor drag: the check judges what is flown
    s.params = TrajectoryParams::load(root.child("trajectory"));
  }
  if (o.periodic) s.params.periodic = true;
  if (!std::isnan(o.dt)) {
    s.params.sample_dt = o.dt;
    if (s.params.check_dt > o.dt) s.params.check_dt = o.dt;
  }
  return s;
}

// A sampled trajectory and its feasibility against the limits at its v_max.
struct Generated {
  Trajectory trajectory;
  FeasibilityReport report;
  FeasibilityLimits limits;
  std::string summary;  // the min-snap polynomial's line; empty for sampled sources
};

// A min-snap polynomial: feasibility checked on the polynomial itself, then sampled.
Generated fromPolynomial(const MinSnapTrajectory& polynomial, double v_max, const Sections& s) {
  Generated g;
  g.limits = FeasibilityLimits::from(s.lqr, v_max, s.params.accel_mismatch_max);
  g.report = checkFeasibility(polynomial, g.limits, s.lqr.gravity, s.params.check_dt);
  g.trajectory = sampleTrajectory(polynomial, s.params.sample_dt, s.lqr.gravity);
  char line[160];
  std::snprintf(line, sizeof(line), "min-snap: %d segments, %.3f s, snap cost %.4g m^2/s^7%s\n",
                polynomial.segmentCount(), polynomial.duration(), polynomial.snapCost(),
                polynomial.periodic ? ", periodic" : ", rest to rest");
  g.summary = line;
  return g;
}

// Samples only (a CSV to check, the ellipse): feasibility checked on the samples.
Generated fromSamples(Trajectory trajectory, double v_max, const Sections& s) {
  Generated g;
  g.trajectory = std::move(trajectory);
  g.limits = FeasibilityLimits::from(s.lqr, v_max, s.params.accel_mismatch_max);
  g.report = checkFeasibility(g.trajectory, g.limits, s.lqr.gravity);
  return g;
}

// Min-snap through a waypoint file's points (.yaml/.yml or .csv); --v-max overrides the file's.
Generated fromWaypointFile(const std::string& source, const Options& o, const Sections& s) {
  WaypointSpec spec;
  if (endsWith(source, ".csv")) spec.waypoints = readWaypointCsv(source);
  else spec = loadWaypointYaml(source);
  MinSnapOptions options;
  options.v_max = !std::isnan(o.v_max) ? o.v_max : spec.v_max;
  if (!(options.v_max > 0.0)) throw std::invalid_argument(source + ": no v_max: give it in the file or with --v-max");
  options.periodic = spec.periodic || o.periodic;
  options.yaw = s.params.yaw;
  options.grid_dt = s.params.check_dt;
  return fromPolynomial(generateMinSnap(spec.waypoints, options), options.v_max, s);
}

Generated generate(const Options& o, const Sections& s) {
  if (!o.check_path.empty()) {
    return fromSamples(readTrajectoryCsv(o.check_path, s.params.sampleChecks()),
                       !std::isnan(o.v_max) ? o.v_max : s.params.fast_v_max, s);
  }
  const std::string& source = o.sources.front();
  if (source == "minsnap_fast") return fromPolynomial(paperMinSnapFast(s.params), s.params.fast_v_max, s);
  if (source == "minsnap_slow") return fromPolynomial(paperMinSnapSlow(s.params), s.params.slow_v_max, s);
  if (source == "ellipse") return fromSamples(paperEllipse(s.params, s.lqr.gravity), s.params.ellipse_speed, s);
  if (endsWith(source, ".yaml") || endsWith(source, ".yml") || endsWith(source, ".csv")) {
    return fromWaypointFile(source, o, s);
  }
  throw std::invalid_argument("unknown SOURCE '" + source + "' (see --help)");
}

// The report goes to stderr when the CSV goes to stdout.
void writeOutputs(const Options& o, const Generated& g) {
  std::ostream& info = o.output_path == "-" ? std::cerr : std::cout;
  const auto& samples = g.trajectory.samples;
  char line[160];
  std::snprintf(line, sizeof(line), "%zu samples over %.3f s%s\n", samples.size(), samples.back().t - samples.front().t,
                g.trajectory.closed ? ", closed" : "");
  info << g.summary << line << formatReport(g.report, g.limits);
  if (o.output_path == "-") writeTrajectoryCsv(std::cout, g.trajectory);
  else if (!o.output_path.empty()) writeTrajectoryCsv(o.output_path, g.trajectory);
}

int run(int argc, const char* const* argv) {
  const Options o = parseOptions(argc, argv);
  const Sections sections = loadSections(o);
  if (o.print_config) {
    printProcessConfig(std::cout, "sdlqr-trajectory", o.config_path,
                       {printedSection("lqr", sections.lqr), printedSection("trajectory", sections.params)});
    return 0;
  }
  Generated generated = generate(o, sections);
  if (o.temporal) generated.trajectory.tracking = ReferenceMode::kTemporal;
  writeOutputs(o, generated);
  return o.require_feasible && !generated.report.feasible() ? kExitInfeasible : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-trajectory", [&] { return run(argc, argv); });
}
