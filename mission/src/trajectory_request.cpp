#include "sdlqr/mission/trajectory_request.hpp"

#include <cstdio>
#include <functional>

#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/waypoint_file.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"

namespace sdlqr::mission {

namespace {

using trajectory::WaypointSpec;

WaypointSpec waypointsOf(const TrajectoryRequest& request) {
  const std::string& path = request.waypoints_path;
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".csv") == 0) {
    WaypointSpec spec;
    spec.waypoints = trajectory::readWaypointCsv(path);
    return spec;
  }
  return trajectory::loadWaypointYaml(path);
}

// The path of a circle, lemniscate or waypoints request at a given peak speed.
std::function<Trajectory(double)> speedPathGenerator(const TrajectoryRequest& request,
                                                     const trajectory::TrajectoryParams& params, double gravity,
                                                     double& requested_speed) {
  if (request.generator == "waypoints") {
    const WaypointSpec spec = waypointsOf(request);
    requested_speed = request.speed > 0.0 ? request.speed : spec.v_max;
    if (!(requested_speed > 0.0)) throw std::invalid_argument("speed: neither the request nor the file gives one");
    return [spec, params, gravity](double speed) {
      trajectory::MinSnapOptions options;
      options.v_max = speed;
      options.periodic = spec.periodic;
      options.yaw = params.yaw;
      options.grid_dt = params.check_dt;
      return trajectory::sampleTrajectory(trajectory::generateMinSnap(spec.waypoints, options), params.sample_dt,
                                          gravity);
    };
  }
  trajectory::ClosedPathSpec spec;
  spec.shape = request.generator == "circle" ? trajectory::ClosedPathShape::kCircle
                                             : trajectory::ClosedPathShape::kLemniscate;
  spec.center = request.center;
  spec.size = request.size;
  spec.yaw = params.yaw;
  spec.sample_dt = request.sample_dt > 0.0 ? request.sample_dt : 0.02;
  requested_speed = request.speed;
  return [spec, gravity](double speed) {
    trajectory::ClosedPathSpec at = spec;
    at.speed = speed;
    return trajectory::sampleClosedPath(at, gravity);
  };
}

// Refused with the feasibility verdict, or flown at the highest feasible speed when asked.
Trajectory buildSpeedPath(const TrajectoryRequest& request, const trajectory::TrajectoryParams& params,
                          const LqrParams& lqr, const std::string& key) {
  double speed = 0.0;
  const auto generate = speedPathGenerator(request, params, lqr.gravity, speed);
  const double v_max = request.v_max > 0.0 ? request.v_max : speed * (1.0 + 1e-9);
  const auto limits = trajectory::FeasibilityLimits::from(lqr, v_max, params.accel_mismatch_max);
  const trajectory::SpeedFit fit = trajectory::fitSpeed(generate, speed, limits, lqr.gravity);
  if (fit.requested.feasible()) return fit.trajectory;
  const std::string verdict = trajectory::describeFit(fit, limits);
  if (!request.scale_if_infeasible || fit.feasible_speed <= 0.0) {
    throw ConfigError(key, verdict + (fit.feasible_speed > 0.0 ? " (on_infeasible: scale flies it there)" : ""));
  }
  std::fprintf(stderr, "sdlqr-mission: %s: %s: flying it at %.3g m/s\n", key.c_str(), verdict.c_str(),
               fit.feasible_speed);
  return fit.trajectory;
}

}  // namespace

Trajectory buildTrajectory(const TrajectoryRequest& request, const trajectory::TrajectoryParams& base,
                           const LqrParams& lqr, const std::string& key) {
  trajectory::TrajectoryParams params = base;
  if (request.laps > 0) params.laps = request.laps;
  if (request.height_offset >= 0.0) params.height_offset = request.height_offset;
  if (request.sample_dt > 0.0) params.sample_dt = request.sample_dt;
  if (!params.valid()) throw ConfigError(key, params.invalidReason());

  Trajectory out;
  try {
    if (request.generator == "minsnap_fast") {
      out = trajectory::sampleTrajectory(trajectory::paperMinSnapFast(params), params.sample_dt, lqr.gravity);
    } else if (request.generator == "minsnap_slow") {
      out = trajectory::sampleTrajectory(trajectory::paperMinSnapSlow(params), params.sample_dt, lqr.gravity);
    } else if (request.generator == "circle" || request.generator == "lemniscate" ||
               request.generator == "waypoints") {
      out = buildSpeedPath(request, params, lqr, key);
    } else if (request.generator == "ellipse") {
      out = trajectory::paperEllipse(params, lqr.gravity);
    } else {
      out = trajectory::readTrajectoryCsv(request.csv_path, params.sampleChecks());
    }
  } catch (const ConfigError&) {
    throw;
  } catch (const std::exception& e) {
    throw ConfigError(key, e.what());
  }
  out.tracking = request.tracking;
  return out;
}

}  // namespace sdlqr::mission
