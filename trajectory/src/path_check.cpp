#include "sdlqr/trajectory/path_check.hpp"

#include <cstdio>

#include "sdlqr/trajectory/speed_fit.hpp"

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

FlatState flatStateAt(const TrajectorySample& sample, double gravity) {
  return flatStateOf(sample.x, sample.u, 0.0, gravity);  // the controller's exit, as it starts one
}

// A stop from every sample the path moves at (a GOTO or LAND may come at any of them), under the
// path's speed as the controller plans it. The plan kept is the first sample's without a stop, else
// the fastest sample's. A path whose samples are beyond the limits is refused (or flown as given)
// whatever its stops: only the fastest sample's is planned, for the report.
void checkExits(PathCheck& check, const Trajectory& path, double path_speed, const LqrParams& lqr,
                const TransitionParams& transition) {
  const size_t fastest = fastestSample(path);
  check.exit_needed = velocity(path.samples[fastest].x).norm() > transition.velocity_tolerance;
  if (!check.exit_needed) return;
  check.exit = planStop(flatStateAt(path.samples[fastest], lqr.gravity), lqr, transition, path_speed);
  check.exit_from_t = path.samples[fastest].t;
  if (!check.samples.feasible()) return;
  double duration_hint = 0.0;  // a stop's duration from the sample before: mostly flyable from the next
  for (const TrajectorySample& sample : path.samples) {
    if (velocity(sample.x).norm() <= transition.velocity_tolerance) continue;
    ++check.exits_checked;
    const FlatState from = flatStateAt(sample, lqr.gravity);
    if (stopExists(from, lqr, transition, path_speed, duration_hint)) continue;
    if (check.exits_missing++ == 0) {
      check.exit = planStop(from, lqr, transition, path_speed);  // its report, for the refusal
      check.exit_from_t = sample.t;
    }
  }
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
  const double path_speed = peakSpeed(path);  // the controller's transitions are planned under it
  if (check.entry_needed) check.entry = planTransition(at_rest, start, lqr, transition, path_speed);
  checkExits(check, path, path_speed, lqr, transition);
  return check;
}

std::string describePathCheck(const PathCheck& check) {
  std::string text = describeViolations(check.samples, check.limits);
  if (!check.transitions) return text;
  text += check.entry_needed ? " " + describeTransition("entry", check.entry) + ";" : " entry: none needed;";
  if (!check.exit_needed) return text + " exit: none needed;";
  char from[96];
  if (check.exits_checked == 0) {  // the samples are beyond the limits: the fastest's alone
    std::snprintf(from, sizeof from, "from the fastest sample (%.3g s)", check.exit_from_t);
  } else if (check.exits_missing == 0) {
    std::snprintf(from, sizeof from, "a stop from each of %d moving samples; from the fastest (%.3g s)",
                  check.exits_checked, check.exit_from_t);
  } else {
    std::snprintf(from, sizeof from, "no stop from %d of %d moving samples; from the first (%.3g s)",
                  check.exits_missing, check.exits_checked, check.exit_from_t);
  }
  return text + " exit: " + describeTransition(from, check.exit) + ";";
}

}  // namespace sdlqr::trajectory
