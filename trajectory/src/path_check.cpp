#include "sdlqr/trajectory/path_check.hpp"

namespace sdlqr::trajectory {

namespace {

// The sample the vehicle flies fastest: the hardest place to have to stop.
size_t fastestSample(const Trajectory& path) {
  size_t fastest = 0;
  for (size_t k = 1; k < path.samples.size(); ++k) {
    if (velocity(path.samples[k].x).norm() > velocity(path.samples[fastest].x).norm()) fastest = k;
  }
  return fastest;
}

}  // namespace

PathCheck checkPath(const Trajectory& path, const FeasibilityLimits& limits, const Vec3& hover, double yaw,
                    const LqrParams& lqr, const TransitionParams& transition) {
  PathCheck check;
  check.limits = limits;
  check.samples = checkFeasibility(path, limits, lqr.gravity);
  check.transitions = transition.enabled && path.samples.size() >= 2;
  if (!check.transitions) return check;
  FlatState at_rest;
  at_rest.position = hover;
  at_rest.yaw = yaw;
  const FlatState start = flatStateAtStart(path, lqr.gravity);
  check.entry_needed = !closeEnough(at_rest, start, transition);
  if (check.entry_needed) check.entry = planTransition(at_rest, start, lqr, transition);
  const TrajectorySample& fastest = path.samples[fastestSample(path)];
  check.exit_needed = velocity(fastest.x).norm() > transition.velocity_tolerance;
  if (check.exit_needed) check.exit = planStop(flatStateOf(fastest.x, fastest.u, 0.0, lqr.gravity), lqr, transition);
  return check;
}

std::string describePathCheck(const PathCheck& check) {
  std::string text = describeViolations(check.samples, check.limits);
  if (!check.transitions) return text;
  text += check.entry_needed ? " " + describeTransition("entry", check.entry) + ";" : " entry: none needed;";
  text += check.exit_needed ? " " + describeTransition("exit", check.exit) + ";" : " exit: none needed;";
  return text;
}

}  // namespace sdlqr::trajectory
