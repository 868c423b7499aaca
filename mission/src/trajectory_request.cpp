#include "sdlqr/mission/trajectory_request.hpp"

#include <cstdio>
#include <functional>
#include <utility>

#include "sdlqr/trajectory/closed_paths.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/path_check.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/speed_fit.hpp"
#include "sdlqr/trajectory/trajectory_csv.hpp"
#include "sdlqr/trajectory/waypoint_file.hpp"

namespace sdlqr::mission {

namespace {

using trajectory::WaypointSpec;

bool isSpeedPath(const TrajectoryRequest& request) {
  return request.generator == "circle" || request.generator == "lemniscate" || request.generator == "waypoints";
}

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

// The paper's paths and CSV files, as given; slower by time scaling.
Trajectory sampledPath(const TrajectoryRequest& request, const trajectory::TrajectoryParams& params, double gravity) {
  if (request.generator == "minsnap_fast") {
    return trajectory::sampleTrajectory(trajectory::paperMinSnapFast(params), params.sample_dt, gravity);
  }
  if (request.generator == "minsnap_slow") {
    return trajectory::sampleTrajectory(trajectory::paperMinSnapSlow(params), params.sample_dt, gravity);
  }
  if (request.generator == "ellipse") return trajectory::paperEllipse(params, gravity);
  return trajectory::readTrajectoryCsv(request.csv_path, params.sampleChecks());
}

std::function<Trajectory(double)> pathGenerator(const TrajectoryRequest& request,
                                                const trajectory::TrajectoryParams& params, double gravity,
                                                double& requested_speed) {
  if (isSpeedPath(request)) return speedPathGenerator(request, params, gravity, requested_speed);
  Trajectory as_given = sampledPath(request, params, gravity);
  requested_speed = trajectory::peakSpeed(as_given);
  return trajectory::givenPathAtSpeed(std::move(as_given), gravity);
}

std::string refusal(const trajectory::SpeedFit& fit, const trajectory::PathCheck& check) {
  const std::string transitions = check.transitions ? trajectory::describePathCheck(check) : "";
  if (!check.samples.feasible()) {
    const std::string speeds = trajectory::describeFit(fit, check.limits);
    return speeds + (fit.feasible_speed > 0.0 ? " (on_infeasible: scale flies it there)" : "");
  }
  return "the way into or out of the path is beyond the vehicle:" + transitions;
}

}  // namespace

Trajectory buildTrajectory(const TrajectoryRequest& request, const trajectory::TrajectoryParams& base,
                           const PathLimits& limits, const Vec3& hover, double yaw, const std::string& key) {
  trajectory::TrajectoryParams params = base;
  if (request.laps > 0) params.laps = request.laps;
  if (request.height_offset >= 0.0) params.height_offset = request.height_offset;
  if (request.sample_dt > 0.0) params.sample_dt = request.sample_dt;
  if (!params.valid()) throw ConfigError(key, params.invalidReason());
  const double gravity = limits.lqr.gravity;

  Trajectory out;
  try {
    double speed = 0.0;
    const auto generate = pathGenerator(request, params, gravity, speed);
    const double v_max = request.v_max > 0.0     ? request.v_max
                         : isSpeedPath(request) ? speed * (1.0 + 1e-9)
                                                : limits.guard.max_speed;
    const auto feasibility = trajectory::FeasibilityLimits::from(limits.lqr, v_max, params.accel_mismatch_max);
    out = generate(speed);
    trajectory::PathCheck check = trajectory::checkPath(out, feasibility, hover, yaw, limits.lqr, limits.transition);
    if (!check.feasible() && request.on_infeasible == OnInfeasible::kFly) {
      std::fprintf(stderr, "sdlqr-mission: %s: flown as given (on_infeasible: fly), beyond the vehicle:%s\n",
                   key.c_str(), trajectory::describePathCheck(check).c_str());
    } else if (!check.feasible()) {
      const trajectory::SpeedFit fit = trajectory::fitSpeed(generate, speed, feasibility, gravity);
      if (request.on_infeasible != OnInfeasible::kScale || fit.feasible_speed <= 0.0) {
        throw ConfigError(key, refusal(fit, check));
      }
      out = fit.trajectory;
      check = trajectory::checkPath(out, feasibility, hover, yaw, limits.lqr, limits.transition);
      if (!check.feasible()) throw ConfigError(key, refusal(fit, check));
      std::fprintf(stderr, "sdlqr-mission: %s: %s: flying it at %.3g m/s\n", key.c_str(),
                   trajectory::describeFit(fit, feasibility).c_str(), fit.feasible_speed);
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
