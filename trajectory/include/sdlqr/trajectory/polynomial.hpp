#pragma once
// One axis of a piecewise polynomial, each segment in normalized time: segment k covers
// [start_k, start_k + T_k] and holds p(tau) = sum_n c_n tau^n with tau = (t - start_k) / T_k.
//
// Normalized time keeps the coefficients of the order of the positions whatever T_k is, which
// keeps the min-snap solve well conditioned, and makes a uniform time scaling exact: scaling
// every T_k by s leaves the coefficients unchanged and divides the n-th derivative by s^n.

#include <vector>

#include <Eigen/Core>

namespace sdlqr::trajectory {

// Degree 9 holds position to snap (derivatives 0..4) at both ends of a segment, so continuity up
// to snap is imposed exactly by sharing these values between neighbouring segments.
inline constexpr int kPolynomialDegree = 9;
inline constexpr int kCoefficientCount = kPolynomialDegree + 1;
inline constexpr int kEndDerivatives = kCoefficientCount / 2;  // orders 0..4 held at each end
using Coefficients = Eigen::Matrix<double, kCoefficientCount, 1>;

class PiecewisePolynomial {
 public:
  PiecewisePolynomial() = default;
  // durations[k] > 0 is T_k; coefficients[k] are c_0..c_9 of segment k in normalized time.
  PiecewisePolynomial(std::vector<double> durations, std::vector<Coefficients> coefficients);
  // The constant `value` over the given segments.
  static PiecewisePolynomial constant(const std::vector<double>& durations, double value);

  int segmentCount() const { return static_cast<int>(durations_.size()); }
  double duration() const { return starts_.empty() ? 0.0 : starts_.back() + durations_.back(); }
  double segmentStart(int k) const { return starts_[k]; }
  double segmentDuration(int k) const { return durations_[k]; }
  const Coefficients& coefficients(int k) const { return coefficients_[k]; }
  const std::vector<double>& durations() const { return durations_; }

  // Segment holding t; t outside [0, duration()] gives the first or last segment.
  int segmentAt(double t) const;
  // d^order p / dt^order at t, t clamped to [0, duration()]; at a knot the later segment answers.
  double evaluate(double t, int order = 0) const;
  // d^order p / dt^order at tau in [0, 1] of segment k: reads either side of a knot.
  double evaluateInSegment(int k, double tau, int order) const;
  // Integral over the whole duration of (d^order p / dt^order)^2 (order 4: the snap cost).
  double squaredDerivativeIntegral(int order) const;
  // The same path flown s times slower (s > 0): p_s(t) = p(t / s).
  PiecewisePolynomial timeScaled(double s) const;

 private:
  std::vector<double> durations_;
  std::vector<double> starts_;
  std::vector<Coefficients> coefficients_;
};

// n! / (n - k)!: the factor d^k/dtau^k brings to the coefficient of tau^n (0 when k > n).
double fallingFactorial(int n, int k);

}  // namespace sdlqr::trajectory
