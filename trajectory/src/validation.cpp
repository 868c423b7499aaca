#include "sdlqr/trajectory/validation.hpp"

#include <cmath>
#include <sstream>

namespace sdlqr::trajectory {

std::string checkSample(const TrajectorySample& sample, const TrajectorySample* previous, const SampleChecks& checks) {
  if (!std::isfinite(sample.t) || !sample.x.allFinite() || !sample.u.allFinite()) return "value not finite";
  if (sample.t < 0.0) return "time negative";
  const double norm = orientation(sample.x).norm();
  if (std::abs(norm - 1.0) > checks.quaternion_norm_tolerance) {
    std::ostringstream why;
    why << "quaternion norm " << norm << " is not 1";
    return why.str();
  }
  if (sample.u[kThrust] < 0.0) return "thrust negative";
  if (previous) {
    if (sample.t <= previous->t) return "time not increasing";
    const double jump = (position(sample.x) - position(previous->x)).norm();
    if (jump > checks.max_position_jump) {
      std::ostringstream why;
      why << "position jump " << jump << " m exceeds " << checks.max_position_jump << " m";
      return why.str();
    }
  }
  return {};
}

std::string checkClosure(const Trajectory& trajectory, const SampleChecks& checks) {
  if (trajectory.samples.size() < 2) return "fewer than 2 samples";
  if (!trajectory.closed) return {};
  const double gap = (position(trajectory.samples.back().x) - position(trajectory.samples.front().x)).norm();
  if (gap > checks.closure_tolerance) {
    std::ostringstream why;
    why << "closed trajectory must end at its first position (" << gap << " m away)";
    return why.str();
  }
  return {};
}

std::string validateTrajectory(const Trajectory& trajectory, const SampleChecks& checks) {
  for (std::size_t k = 0; k < trajectory.samples.size(); ++k) {
    const TrajectorySample* previous = k > 0 ? &trajectory.samples[k - 1] : nullptr;
    const std::string why = checkSample(trajectory.samples[k], previous, checks);
    if (!why.empty()) return "sample " + std::to_string(k) + ": " + why;
  }
  return checkClosure(trajectory, checks);
}

}  // namespace sdlqr::trajectory
