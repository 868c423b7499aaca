#include "sdlqr/trajectory/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sdlqr::trajectory {

double fallingFactorial(int n, int k) {
  if (k > n) return 0.0;
  double f = 1.0;
  for (int i = 0; i < k; ++i) f *= static_cast<double>(n - i);
  return f;
}

PiecewisePolynomial::PiecewisePolynomial(std::vector<double> durations, std::vector<Coefficients> coefficients)
    : durations_(std::move(durations)), coefficients_(std::move(coefficients)) {
  if (durations_.empty() || durations_.size() != coefficients_.size()) {
    throw std::invalid_argument("piecewise polynomial: need one coefficient vector per segment, at least one");
  }
  starts_.resize(durations_.size());
  double start = 0.0;
  for (std::size_t k = 0; k < durations_.size(); ++k) {
    if (!std::isfinite(durations_[k]) || durations_[k] <= 0.0) {
      throw std::invalid_argument("piecewise polynomial: segment durations must be finite and > 0");
    }
    starts_[k] = start;
    start += durations_[k];
  }
}

PiecewisePolynomial PiecewisePolynomial::constant(const std::vector<double>& durations, double value) {
  Coefficients c = Coefficients::Zero();
  c[0] = value;
  return PiecewisePolynomial(durations, std::vector<Coefficients>(durations.size(), c));
}

int PiecewisePolynomial::segmentAt(double t) const {
  // The first segment starting after t, minus one.
  const auto after = std::upper_bound(starts_.begin(), starts_.end(), t);
  const int k = static_cast<int>(after - starts_.begin()) - 1;
  return std::clamp(k, 0, segmentCount() - 1);
}

double PiecewisePolynomial::evaluate(double t, int order) const {
  const double clamped = std::clamp(t, 0.0, duration());
  const int k = segmentAt(clamped);
  const double tau = std::clamp((clamped - starts_[k]) / durations_[k], 0.0, 1.0);
  return evaluateInSegment(k, tau, order);
}

double PiecewisePolynomial::evaluateInSegment(int k, double tau, int order) const {
  const Coefficients& c = coefficients_[k];
  // Horner on sum_{n >= order} n!/(n-order)! c_n tau^(n-order).
  double value = 0.0;
  for (int n = kPolynomialDegree; n >= order; --n) value = value * tau + fallingFactorial(n, order) * c[n];
  return value / std::pow(durations_[k], order);
}

double PiecewisePolynomial::squaredDerivativeIntegral(int order) const {
  double total = 0.0;
  for (int k = 0; k < segmentCount(); ++k) {
    const Coefficients& c = coefficients_[k];
    double normalized = 0.0;  // integral over tau in [0, 1]
    for (int n = order; n <= kPolynomialDegree; ++n) {
      for (int m = order; m <= kPolynomialDegree; ++m) {
        normalized += fallingFactorial(n, order) * fallingFactorial(m, order) * c[n] * c[m] / (n + m - 2 * order + 1);
      }
    }
    // dt = T dtau and each derivative carries 1/T.
    total += normalized * std::pow(durations_[k], 1 - 2 * order);
  }
  return total;
}

PiecewisePolynomial PiecewisePolynomial::timeScaled(double s) const {
  if (!std::isfinite(s) || s <= 0.0) throw std::invalid_argument("time scale must be finite and > 0");
  std::vector<double> scaled = durations_;
  for (double& d : scaled) d *= s;
  return PiecewisePolynomial(std::move(scaled), coefficients_);
}

}  // namespace sdlqr::trajectory
