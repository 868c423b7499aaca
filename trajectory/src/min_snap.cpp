#include "sdlqr/trajectory/min_snap.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace sdlqr::trajectory {

namespace {

// The solve runs in long double: the Hermite map of degree 9 and the snap Hessian are badly
// scaled (entries from 1 to 9!/4!), and the extra bits keep the result exact to double rounding.
using Real = long double;
using SegmentMatrix = Eigen::Matrix<Real, kCoefficientCount, kCoefficientCount>;
using SegmentVector = Eigen::Matrix<Real, kCoefficientCount, 1>;
using RealMatrix = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
using RealVector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
constexpr int kSnapOrder = 4;

// Maps c (normalized time) to the end derivatives d^k p/dtau^k, k = 0..4 at tau = 0 then tau = 1.
SegmentMatrix normalizedEndDerivativeMap() {
  SegmentMatrix map = SegmentMatrix::Zero();
  for (int k = 0; k < kEndDerivatives; ++k) {
    map(k, k) = fallingFactorial(k, k);
    for (int n = k; n < kCoefficientCount; ++n) map(kEndDerivatives + k, n) = fallingFactorial(n, k);
  }
  return map;
}

// integral over tau in [0, 1] of (d^4 p/dtau^4)^2 = c^T H c.
SegmentMatrix normalizedSnapHessian() {
  SegmentMatrix h = SegmentMatrix::Zero();
  for (int n = kSnapOrder; n < kCoefficientCount; ++n) {
    for (int m = kSnapOrder; m < kCoefficientCount; ++m) {
      h(n, m) = static_cast<Real>(fallingFactorial(n, kSnapOrder) * fallingFactorial(m, kSnapOrder)) /
                (n + m - 2 * kSnapOrder + 1);
    }
  }
  return h;
}

const SegmentMatrix& inverseEndDerivativeMap() {
  static const SegmentMatrix inverse = normalizedEndDerivativeMap().inverse();
  return inverse;
}

// c = coefficientMap(T) e, with e the physical end derivatives (d^k p/dt^k = T^-k d^k p/dtau^k).
SegmentMatrix coefficientMap(double duration) {
  SegmentMatrix to_normalized = SegmentMatrix::Zero();
  for (int k = 0; k < kEndDerivatives; ++k) {
    const Real scale = std::pow(static_cast<Real>(duration), k);
    to_normalized(k, k) = scale;
    to_normalized(kEndDerivatives + k, kEndDerivatives + k) = scale;
  }
  return inverseEndDerivativeMap() * to_normalized;
}

// Snap cost of one segment as a quadratic form in its physical end derivatives.
SegmentMatrix endDerivativeCost(double duration) {
  static const SegmentMatrix hessian = normalizedSnapHessian();
  const SegmentMatrix map = coefficientMap(duration);
  return map.transpose() * hessian * map / std::pow(static_cast<Real>(duration), 2 * kSnapOrder - 1);
}

std::string indexed(const char* name, std::size_t i) {
  std::ostringstream s;
  s << name << "[" << i << "]";
  return s.str();
}

double wrapToPi(double angle) { return angle - 2.0 * M_PI * std::floor((angle + M_PI) / (2.0 * M_PI)); }

// Index into the node-derivative vector of local end derivative `local` (0..9) of a segment.
int globalIndex(int nodes, int segment, int local) {
  const int node = local < kEndDerivatives ? segment : (segment + 1) % nodes;
  return node * kEndDerivatives + local % kEndDerivatives;
}

PiecewisePolynomial polynomialFromNodes(const RealVector& z, const std::vector<double>& durations, bool periodic,
                                        double wrap_offset) {
  const int nodes = static_cast<int>(z.size()) / kEndDerivatives;
  const int segments = static_cast<int>(durations.size());
  std::vector<Coefficients> coefficients(segments);
  for (int k = 0; k < segments; ++k) {
    if (!(durations[k] > 0.0)) throw std::invalid_argument("min-snap: segment durations must be > 0");
    SegmentVector ends;
    for (int local = 0; local < kCoefficientCount; ++local) ends[local] = z[globalIndex(nodes, k, local)];
    if (periodic && k == segments - 1) ends[kEndDerivatives] += wrap_offset;
    coefficients[k] = (coefficientMap(durations[k]) * ends).cast<double>();
  }
  return PiecewisePolynomial(durations, std::move(coefficients));
}

}  // namespace

PiecewisePolynomial solveMinSnapAxis(const std::vector<double>& node_values, const std::vector<double>& durations,
                                     bool periodic, double wrap_offset) {
  const int nodes = static_cast<int>(node_values.size());
  const int segments = static_cast<int>(durations.size());
  if (nodes < 2) throw std::invalid_argument("min-snap: need at least 2 waypoints");
  if (segments != (periodic ? nodes : nodes - 1)) throw std::invalid_argument("min-snap: wrong number of segment durations");
  for (double d : durations) {
    if (!std::isfinite(d) || d <= 0.0) throw std::invalid_argument("min-snap: segment durations must be finite and > 0");
  }
  for (double v : node_values) {
    if (!std::isfinite(v)) throw std::invalid_argument("min-snap: waypoint values must be finite");
  }

  // z holds derivative `order` of node j at j * kEndDerivatives + order.
  const int unknowns = nodes * kEndDerivatives;
  RealVector z = RealVector::Zero(unknowns);
  std::vector<bool> fixed(unknowns, false);
  for (int j = 0; j < nodes; ++j) {
    z[j * kEndDerivatives] = node_values[j];
    fixed[j * kEndDerivatives] = true;
  }
  if (!periodic) {
    // Start and end at rest: velocity, acceleration and jerk zero (snap stays free).
    for (int order = 1; order < kSnapOrder; ++order) {
      fixed[order] = true;
      fixed[(nodes - 1) * kEndDerivatives + order] = true;
    }
  }

  // Total cost z^T Q z + 2 b^T z + const; b comes from the wrap offset of the last segment.
  RealMatrix q = RealMatrix::Zero(unknowns, unknowns);
  RealVector b = RealVector::Zero(unknowns);
  for (int k = 0; k < segments; ++k) {
    const SegmentMatrix cost = endDerivativeCost(durations[k]);
    for (int r = 0; r < kCoefficientCount; ++r) {
      for (int c = 0; c < kCoefficientCount; ++c) q(globalIndex(nodes, k, r), globalIndex(nodes, k, c)) += cost(r, c);
      if (periodic && k == segments - 1) b[globalIndex(nodes, k, r)] += cost(r, kEndDerivatives) * wrap_offset;
    }
  }

  std::vector<int> free_index;
  for (int i = 0; i < unknowns; ++i) {
    if (!fixed[i]) free_index.push_back(i);
  }
  const int free_count = static_cast<int>(free_index.size());
  if (free_count > 0) {
    RealMatrix q_free(free_count, free_count);
    RealVector rhs(free_count);
    for (int r = 0; r < free_count; ++r) {
      Real known = b[free_index[r]];
      for (int c = 0; c < unknowns; ++c) {
        if (fixed[c]) known += q(free_index[r], c) * z[c];
      }
      rhs[r] = -known;
      for (int c = 0; c < free_count; ++c) q_free(r, c) = q(free_index[r], free_index[c]);
    }
    // Derivatives of different orders differ by orders of magnitude: equilibrate before Cholesky.
    const RealVector scale = q_free.diagonal().cwiseSqrt().cwiseInverse();
    const RealMatrix scaled = scale.asDiagonal() * q_free * scale.asDiagonal();
    const Eigen::LLT<RealMatrix> cholesky(scaled);
    if (cholesky.info() != Eigen::Success) throw std::invalid_argument("min-snap: cost not positive definite");
    const RealVector solution = scale.cwiseProduct(cholesky.solve(scale.cwiseProduct(rhs)));
    if (!solution.allFinite()) throw std::invalid_argument("min-snap: solve produced non-finite values");
    for (int r = 0; r < free_count; ++r) z[free_index[r]] = solution[r];
  }
  return polynomialFromNodes(z, durations, periodic, wrap_offset);
}

PiecewisePolynomial fromNodeDerivatives(const Eigen::MatrixXd& node_derivatives, const std::vector<double>& durations,
                                        bool periodic, double wrap_offset) {
  const int nodes = static_cast<int>(node_derivatives.rows());
  const int segments = static_cast<int>(durations.size());
  if (node_derivatives.cols() != kEndDerivatives || nodes < 2 || segments != (periodic ? nodes : nodes - 1)) {
    throw std::invalid_argument("node derivatives: need one row of 5 per node and one duration per segment");
  }
  RealVector z(nodes * kEndDerivatives);
  for (int j = 0; j < nodes; ++j) {
    for (int order = 0; order < kEndDerivatives; ++order) z[j * kEndDerivatives + order] = node_derivatives(j, order);
  }
  return polynomialFromNodes(z, durations, periodic, wrap_offset);
}

FlatOutput MinSnapTrajectory::evaluate(double t) const {
  FlatOutput out;
  out.t = t;
  double local = std::clamp(t, 0.0, duration());
  double laps = 0.0;
  if (periodic && std::isfinite(t)) {
    laps = std::floor(t / duration());
    local = std::clamp(t - laps * duration(), 0.0, duration());
  } else {
    out.t = local;
  }
  for (int axis = 0; axis < 3; ++axis) {
    out.position[axis] = axes[axis].evaluate(local, 0);
    out.velocity[axis] = axes[axis].evaluate(local, 1);
    out.acceleration[axis] = axes[axis].evaluate(local, 2);
    out.jerk[axis] = axes[axis].evaluate(local, 3);
    out.snap[axis] = axes[axis].evaluate(local, 4);
  }
  // A periodic heading may turn by a multiple of 2 pi per lap; keep counting instead of jumping back.
  const double turn_per_lap = periodic ? yaw.evaluate(duration(), 0) - yaw.evaluate(0.0, 0) : 0.0;
  out.yaw = yaw.evaluate(local, 0) + laps * turn_per_lap;
  out.yaw_rate = yaw.evaluate(local, 1);
  return out;
}

double MinSnapTrajectory::snapCost() const {
  double cost = 0.0;
  for (const PiecewisePolynomial& axis : axes) cost += axis.squaredDerivativeIntegral(kSnapOrder);
  return cost;
}

MinSnapTrajectory MinSnapTrajectory::timeScaled(double s) const {
  MinSnapTrajectory scaled = *this;
  for (PiecewisePolynomial& axis : scaled.axes) axis = axis.timeScaled(s);
  scaled.yaw = yaw.timeScaled(s);
  return scaled;
}

namespace {

void checkWaypoints(const std::vector<Waypoint>& waypoints, bool periodic) {
  if (waypoints.size() < 2) throw std::invalid_argument("min-snap: need at least 2 waypoints");
  const bool yaw_given = waypoints.front().has_yaw;
  for (std::size_t i = 0; i < waypoints.size(); ++i) {
    const Waypoint& w = waypoints[i];
    if (!w.position.allFinite() || (w.has_yaw && !std::isfinite(w.yaw))) {
      throw std::invalid_argument(indexed("waypoints", i) + ": not finite");
    }
    if (w.has_yaw != yaw_given) throw std::invalid_argument(indexed("waypoints", i) + ": give yaw on every waypoint or on none");
    if (i > 0 && (w.position - waypoints[i - 1].position).norm() < 1e-9) {
      throw std::invalid_argument(indexed("waypoints", i) + ": same position as the previous waypoint");
    }
  }
  if (periodic && (waypoints.back().position - waypoints.front().position).norm() < 1e-9) {
    throw std::invalid_argument("waypoints: a periodic path closes by itself; do not repeat the first waypoint at the end");
  }
}

}  // namespace

std::vector<double> durationsFromDistances(const std::vector<Waypoint>& waypoints, bool periodic, double speed) {
  checkWaypoints(waypoints, periodic);
  if (!std::isfinite(speed) || speed <= 0.0) throw std::invalid_argument("min-snap: speed must be finite and > 0");
  const std::size_t segments = periodic ? waypoints.size() : waypoints.size() - 1;
  std::vector<double> durations(segments);
  for (std::size_t k = 0; k < segments; ++k) {
    const Vec3& from = waypoints[k].position;
    const Vec3& to = waypoints[(k + 1) % waypoints.size()].position;
    durations[k] = (to - from).norm() / speed;
  }
  return durations;
}

MinSnapTrajectory solveMinSnap(const std::vector<Waypoint>& waypoints, const std::vector<double>& durations,
                               bool periodic, double fixed_yaw) {
  checkWaypoints(waypoints, periodic);
  if (!std::isfinite(fixed_yaw)) throw std::invalid_argument("min-snap: yaw must be finite");
  MinSnapTrajectory out;
  out.periodic = periodic;
  std::vector<double> values(waypoints.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t i = 0; i < waypoints.size(); ++i) values[i] = waypoints[i].position[axis];
    out.axes[axis] = solveMinSnapAxis(values, durations, periodic);
  }
  if (!waypoints.front().has_yaw) {
    out.yaw = PiecewisePolynomial::constant(durations, fixed_yaw);
    return out;
  }
  // Unwrap so each step turns the short way; a periodic path may end a multiple of 2 pi away.
  values[0] = waypoints[0].yaw;
  for (std::size_t i = 1; i < waypoints.size(); ++i) {
    values[i] = values[i - 1] + wrapToPi(waypoints[i].yaw - values[i - 1]);
  }
  double wrap_offset = 0.0;
  if (periodic) {
    const double back_to_start = values.back() + wrapToPi(values.front() - values.back());
    wrap_offset = back_to_start - values.front();
  }
  out.yaw = solveMinSnapAxis(values, durations, periodic, wrap_offset);
  return out;
}

namespace {

// Maximum of a smooth f on [lo, hi] by golden-section search (f unimodal there).
template <typename F>
double refineMaximum(const F& f, double lo, double hi) {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = hi - ratio * (hi - lo);
  double b = lo + ratio * (hi - lo);
  double fa = f(a);
  double fb = f(b);
  for (int iteration = 0; iteration < 60 && hi - lo > 1e-12; ++iteration) {
    if (fa < fb) {
      lo = a;
      a = b;
      fa = fb;
      b = lo + ratio * (hi - lo);
      fb = f(b);
    } else {
      hi = b;
      b = a;
      fb = fa;
      a = hi - ratio * (hi - lo);
      fa = f(a);
    }
  }
  return std::max(fa, fb);
}

}  // namespace

double maxSpeed(const MinSnapTrajectory& trajectory, double grid_dt) {
  if (!std::isfinite(grid_dt) || grid_dt <= 0.0) throw std::invalid_argument("speed grid step must be > 0");
  const double duration = trajectory.duration();
  auto speed = [&](double t) {
    Vec3 v;
    for (int axis = 0; axis < 3; ++axis) v[axis] = trajectory.axes[axis].evaluate(t, 1);
    return v.norm();
  };
  const long steps = std::max(2L, static_cast<long>(std::ceil(duration / grid_dt)));
  const double step = duration / static_cast<double>(steps);
  std::vector<double> grid(steps + 1);
  for (long i = 0; i <= steps; ++i) grid[i] = speed(static_cast<double>(i) * step);
  // Several local maxima can be nearly equal (symmetric paths): refine every one of them.
  double best = 0.0;
  for (long i = 0; i <= steps; ++i) {
    best = std::max(best, grid[i]);
    const bool rises = i == 0 || grid[i] >= grid[i - 1];
    const bool falls = i == steps || grid[i] >= grid[i + 1];
    if (rises && falls) {
      const double lo = static_cast<double>(std::max(0L, i - 1)) * step;
      const double hi = static_cast<double>(std::min(steps, i + 1)) * step;
      best = std::max(best, refineMaximum(speed, lo, hi));
    }
  }
  return best;
}

MinSnapTrajectory generateMinSnap(const std::vector<Waypoint>& waypoints, const MinSnapOptions& options) {
  if (!std::isfinite(options.v_max) || options.v_max <= 0.0) throw std::invalid_argument("min-snap: v_max must be > 0");
  const MinSnapTrajectory initial =
      solveMinSnap(waypoints, durationsFromDistances(waypoints, options.periodic, options.v_max), options.periodic,
                   options.yaw);
  const double top_speed = maxSpeed(initial, options.grid_dt);
  return initial.timeScaled(top_speed / options.v_max);
}

}  // namespace sdlqr::trajectory
