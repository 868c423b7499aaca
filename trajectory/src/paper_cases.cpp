#include "sdlqr/trajectory/paper_cases.hpp"

#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::trajectory {

namespace {
constexpr double kEllipseRadii[3] = {1.5, 1.2, 0.5};  // [m] r_x, r_y, r_z of §III-C.3
}  // namespace

std::vector<Waypoint> paperWaypoints(double height_offset) {
  const Vec3 lift(0.0, 0.0, height_offset);
  std::vector<Waypoint> out(4);
  out[0].position = Vec3(0.0, -1.2, 0.0) + lift;
  out[1].position = Vec3(1.5, 0.0, 0.5) + lift;
  out[2].position = Vec3(0.0, 1.5, 0.0) + lift;
  out[3].position = Vec3(-1.5, 0.0, 0.5) + lift;
  return out;
}

std::vector<Waypoint> paperPathWaypoints(const TrajectoryParams& params) {
  const std::vector<Waypoint> corners = paperWaypoints(params.height_offset);
  if (params.periodic) return corners;
  std::vector<Waypoint> path{corners[0]};
  for (int lap = 0; lap < params.laps; ++lap) {
    path.insert(path.end(), corners.begin() + 1, corners.end());
    path.push_back(corners[0]);
  }
  return path;
}

MinSnapTrajectory paperMinSnap(double v_max, const TrajectoryParams& params) {
  MinSnapOptions options;
  options.v_max = v_max;
  options.periodic = params.periodic;
  options.yaw = params.yaw;
  options.grid_dt = params.check_dt;
  return generateMinSnap(paperPathWaypoints(params), options);
}

MinSnapTrajectory paperMinSnapFast(const TrajectoryParams& params) { return paperMinSnap(params.fast_v_max, params); }
MinSnapTrajectory paperMinSnapSlow(const TrajectoryParams& params) { return paperMinSnap(params.slow_v_max, params); }

Vec3 paperEllipsePoint(double alpha, double height_offset) {
  return Vec3(kEllipseRadii[0] * std::sin(alpha), -kEllipseRadii[1] * std::cos(alpha),
              kEllipseRadii[2] * std::sin(alpha) + height_offset);
}

Trajectory paperEllipse(const TrajectoryParams& params, double gravity) {
  const int n = params.ellipse_samples;
  auto point = [&](int k) { return paperEllipsePoint(2.0 * M_PI * (k % n) / n, params.height_offset); };
  const Quat level = quat::fromYaw(params.yaw);
  const Input hover = makeInput(Vec3::Zero(), gravity);

  Trajectory out;
  out.closed = true;
  out.samples.resize(n + 1);
  double t = 0.0;
  for (int k = 0; k <= n; ++k) {
    const Vec3 here = point(k);
    const Vec3 step = point(k + 1) - here;
    TrajectorySample& s = out.samples[k];
    s.t = t;
    s.x = makeState(here, level, params.ellipse_speed * step.normalized());
    s.u = hover;
    t += step.norm() / params.ellipse_speed;
  }
  return out;
}

}  // namespace sdlqr::trajectory
