#pragma once
// Minimum-snap trajectories through waypoints (Mellinger & Kumar, ICRA 2011), solved in the
// unconstrained form of Richter, Bry & Roy (ISRR 2013):
//
// Each axis is a piecewise polynomial of degree 9 (polynomial.hpp). The unknowns are the
// derivatives of orders 0..4 at every waypoint ("node"), shared by the two segments meeting
// there, so continuity up to snap holds by construction. A segment's 10 coefficients follow
// linearly from its 10 end derivatives, so the snap cost sum_k integral |p''''|^2 is a quadratic
// form in the node derivatives. Fixed: every position, and for an open trajectory velocity,
// acceleration and jerk zero at both ends (start and end at rest). Free: everything else. Setting
// the gradient of the cost with respect to the free derivatives to zero gives one symmetric
// positive definite system (Cholesky). The optimum is the classic degree-7, C^6 spline: the
// solution's derivatives 5 and 6 come out continuous too, which the tests check.
//
// Periodic (closed) trajectories have no rest conditions: the last segment returns to the first
// waypoint and shares its derivatives, so the path is C^4 across the wrap and laps repeat.
//
// Yaw is its own axis solved the same way when every waypoint gives one (unwrapped so each step
// turns by at most pi); otherwise yaw stays at a fixed value.

#include <array>
#include <string>
#include <vector>

#include "sdlqr/math/types.hpp"
#include "sdlqr/trajectory/flatness.hpp"
#include "sdlqr/trajectory/polynomial.hpp"

namespace sdlqr::trajectory {

struct Waypoint {
  Vec3 position = Vec3::Zero();  // [m] world
  double yaw = 0.0;              // [rad] used only when has_yaw
  bool has_yaw = false;
};

// One axis from its node derivatives (Richter's parameterization): row j of node_derivatives holds
// derivatives 0..4 at node j; segment k runs from node k to node k+1 (to node 0 when periodic,
// arriving at value + wrap_offset). The min-snap solution is the choice of the free entries.
PiecewisePolynomial fromNodeDerivatives(const Eigen::MatrixXd& node_derivatives, const std::vector<double>& durations,
                                        bool periodic, double wrap_offset = 0.0);

// One axis: node values (one per waypoint), segment durations (one per segment: waypoints - 1
// when open, waypoints when periodic). `wrap_offset` is added to the first value where the
// periodic path comes back to it (2 pi k for an unwrapped yaw). Throws std::invalid_argument.
PiecewisePolynomial solveMinSnapAxis(const std::vector<double>& node_values, const std::vector<double>& durations,
                                     bool periodic, double wrap_offset = 0.0);

struct MinSnapTrajectory {
  std::array<PiecewisePolynomial, 3> axes;  // x, y, z [m]
  PiecewisePolynomial yaw;                  // [rad]
  bool periodic = false;

  double duration() const { return axes[0].duration(); }
  int segmentCount() const { return axes[0].segmentCount(); }
  // Flat outputs at t: clamped to [0, duration()] when open; periodic repeats laps for any t.
  FlatOutput evaluate(double t) const;
  // Sum over x, y, z of the integral of the squared snap [m^2/s^7].
  double snapCost() const;
  // The same path flown s times slower.
  MinSnapTrajectory timeScaled(double s) const;
};

// The min-snap trajectory for given segment durations [s]. Throws std::invalid_argument on fewer
// than two waypoints, non-finite values, a waypoint on the position of its predecessor, yaw on
// some waypoints but not all, or a wrong number of durations.
MinSnapTrajectory solveMinSnap(const std::vector<Waypoint>& waypoints, const std::vector<double>& durations,
                               bool periodic, double fixed_yaw = 0.0);

// Initial time allocation: segment k takes its straight-line length / speed.
std::vector<double> durationsFromDistances(const std::vector<Waypoint>& waypoints, bool periodic, double speed);

// Largest speed [m/s] on a grid of step grid_dt over the whole trajectory, refined around the
// largest grid value by a golden-section search (so it does not depend on where the grid falls).
double maxSpeed(const MinSnapTrajectory& trajectory, double grid_dt);

struct MinSnapOptions {
  double v_max = 3.0;      // [m/s]
  bool periodic = false;
  double yaw = 0.0;        // [rad] heading when the waypoints give none
  double grid_dt = 1e-3;   // [s] grid of the speed check
};

// Time allocation from distances, then one uniform time scaling so the top speed equals v_max.
// Min-snap solutions are invariant under uniform scaling (the scaled solution is the optimum for
// the scaled durations), so one scaling is exact: no iteration.
MinSnapTrajectory generateMinSnap(const std::vector<Waypoint>& waypoints, const MinSnapOptions& options);

}  // namespace sdlqr::trajectory
