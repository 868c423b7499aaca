#pragma once
// Aggressive closed paths at a user-set speed: a horizontal circle and a lemniscate of Gerono
// (a figure eight), flown at a constant phase rate so every derivative is exact and the flat map
// (flatness.hpp) gives exact inputs. One closed lap per Trajectory (README: closed trajectories),
// its last sample on the first; laps repeat until the next command.
//
//   circle      p = center + r (cos w t, sin w t, 0),                |v| = r w everywhere
//   lemniscate  p = center + a (sin w t, sin w t cos w t, 0),        |v| peaks at a w sqrt(2)
//                                                                    where it crosses the center
// `speed` is the peak speed: w follows from it. Whether the vehicle can fly it is the feasibility
// report's verdict (checkFeasibility of the samples), not this file's.

#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/flatness.hpp"

namespace sdlqr::trajectory {

enum class ClosedPathShape { kCircle, kLemniscate };

struct ClosedPathSpec {
  ClosedPathShape shape = ClosedPathShape::kCircle;
  Vec3 center = Vec3(0.0, 0.0, 1.0);  // [m] world
  double size = 1.0;                  // [m] circle radius, lemniscate half-width a
  double speed = 1.0;                 // [m/s] peak speed along the path
  double yaw = 0.0;                   // [rad] fixed heading
  double sample_dt = 0.02;            // [s]
};

// Empty when valid, else "key: reason" (speed, size, sample_dt).
std::string closedPathInvalidReason(const ClosedPathSpec& spec);
double closedPathPeriod(const ClosedPathSpec& spec);  // [s] one lap
FlatOutput closedPathAt(const ClosedPathSpec& spec, double t);
// Throws std::invalid_argument when the spec is invalid.
Trajectory sampleClosedPath(const ClosedPathSpec& spec, double gravity);

}  // namespace sdlqr::trajectory
