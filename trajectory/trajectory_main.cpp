// sdlqr-trajectory: generate the paper's reference trajectories (or min-snap through your
// waypoints), write them as CSV and print their feasibility against the LQR limits.
// Not a bus process: the scenario player uploads the CSV it writes.

#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <string>
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

int run(int argc, const char* const* argv) {
  Options o;
  ArgParser parser("sdlqr-trajectory",
                   "Generates a reference trajectory, writes it as CSV and reports its feasibility against the\n"
                   "LQR limits (c_min, c_max, omega_max of the lqr section) and v_max.\n"
                   "SOURCE is minsnap_fast (paper III-C.2), minsnap_slow (III-C.4), ellipse (III-C.3, infeasible\n"
                   "by design) or a waypoint file (.yaml/.yml or .csv, see trajectory/README.md).");
  parser.addOption("--config", &o.config_path, "FILE", "vehicle file: lqr limits and the trajectory section");
  parser.addOption("--output", &o.output_path, "FILE", "write the sampled trajectory as CSV ('-': stdout)");
  parser.addOption("--check", &o.check_path, "FILE", "validate a trajectory CSV and report its feasibility");
  parser.addOption("--v-max", &o.v_max, "M_PER_S", "top speed for a waypoint file (overrides its v_max)");
  parser.addOption("--dt", &o.dt, "SECONDS", "sample spacing (default trajectory.sample_dt, 0.1 s)");
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
  LqrParams lqr;
  TrajectoryParams params;
  if (!o.config_path.empty()) {
    const ConfigReader root = loadVehicleConfig(o.config_path);
    lqr = LqrParams::load(root.child("lqr"));
    params = TrajectoryParams::load(root.child("trajectory"));
  }
  if (o.periodic) params.periodic = true;
  if (!std::isnan(o.dt)) {
    if (!(o.dt > 0.0)) throw std::invalid_argument("--dt: must be > 0");
    params.sample_dt = o.dt;
    if (params.check_dt > o.dt) params.check_dt = o.dt;
  }
  if (o.print_config) {
    printProcessConfig(std::cout, "sdlqr-trajectory", o.config_path,
                       {printedSection("lqr", lqr), printedSection("trajectory", params)});
    return 0;
  }
  const bool v_max_given = !std::isnan(o.v_max);
  if (v_max_given && !(o.v_max > 0.0)) throw std::invalid_argument("--v-max: must be > 0");

  Trajectory trajectory;
  FeasibilityReport report;
  FeasibilityLimits limits;
  std::string summary;
  auto fromPolynomial = [&](const MinSnapTrajectory& polynomial, double v_max) {
    limits = FeasibilityLimits::from(lqr, v_max, params.accel_mismatch_max);
    report = checkFeasibility(polynomial, limits, lqr.gravity, params.check_dt);
    trajectory = sampleTrajectory(polynomial, params.sample_dt, lqr.gravity);
    char line[160];
    std::snprintf(line, sizeof(line), "min-snap: %d segments, %.3f s, snap cost %.4g m^2/s^7%s\n",
                  polynomial.segmentCount(), polynomial.duration(), polynomial.snapCost(),
                  polynomial.periodic ? ", periodic" : ", rest to rest");
    summary = line;
  };
  auto fromSamples = [&](double v_max) {
    limits = FeasibilityLimits::from(lqr, v_max, params.accel_mismatch_max);
    report = checkFeasibility(trajectory, limits, lqr.gravity);
  };

  if (!o.check_path.empty()) {
    trajectory = readTrajectoryCsv(o.check_path, params.sampleChecks());
    fromSamples(v_max_given ? o.v_max : params.fast_v_max);
  } else {
    const std::string& source = o.sources.front();
    if (source == "minsnap_fast") {
      fromPolynomial(paperMinSnapFast(params), params.fast_v_max);
    } else if (source == "minsnap_slow") {
      fromPolynomial(paperMinSnapSlow(params), params.slow_v_max);
    } else if (source == "ellipse") {
      trajectory = paperEllipse(params, lqr.gravity);
      fromSamples(params.ellipse_speed);
    } else if (endsWith(source, ".yaml") || endsWith(source, ".yml") || endsWith(source, ".csv")) {
      WaypointSpec spec;
      if (endsWith(source, ".csv")) spec.waypoints = readWaypointCsv(source);
      else spec = loadWaypointYaml(source);
      MinSnapOptions options;
      options.v_max = v_max_given ? o.v_max : spec.v_max;
      if (!(options.v_max > 0.0)) throw std::invalid_argument(source + ": no v_max: give it in the file or with --v-max");
      options.periodic = spec.periodic || o.periodic;
      options.yaw = params.yaw;
      options.grid_dt = params.check_dt;
      fromPolynomial(generateMinSnap(spec.waypoints, options), options.v_max);
    } else {
      throw std::invalid_argument("unknown SOURCE '" + source + "' (see --help)");
    }
  }
  if (o.temporal) trajectory.tracking = ReferenceMode::kTemporal;

  // The report goes to stderr when the CSV goes to stdout.
  std::ostream& info = o.output_path == "-" ? std::cerr : std::cout;
  const auto& samples = trajectory.samples;
  char line[160];
  std::snprintf(line, sizeof(line), "%zu samples over %.3f s%s\n", samples.size(), samples.back().t - samples.front().t,
                trajectory.closed ? ", closed" : "");
  info << summary << line << formatReport(report, limits);
  if (o.output_path == "-") writeTrajectoryCsv(std::cout, trajectory);
  else if (!o.output_path.empty()) writeTrajectoryCsv(o.output_path, trajectory);
  return o.require_feasible && !report.feasible() ? kExitInfeasible : 0;
}

}  // namespace

int main(int argc, char** argv) {
  return sdlqr::runMain("sdlqr-trajectory", [&] { return run(argc, argv); });
}
