#pragma once
// The accepted values of one number parameter: an interval whose ends are open, closed or absent.
// A non-finite value is never accepted. rule() is the reason a refused value gets ("must be in
// (0, 1] s"), so the check and its message cannot disagree.

#include <cmath>
#include <limits>
#include <string>

namespace sdlqr {

struct Range {
  double low = -std::numeric_limits<double>::infinity();
  double high = std::numeric_limits<double>::infinity();
  bool low_open = false;
  bool high_open = false;

  static constexpr Range finite() { return Range{}; }
  static constexpr Range above(double low) { return {low, kInf, true, false}; }      // (low, inf)
  static constexpr Range atLeast(double low) { return {low, kInf, false, false}; }   // [low, inf)
  static constexpr Range closed(double low, double high) { return {low, high, false, false}; }  // [low, high]
  static constexpr Range open(double low, double high) { return {low, high, true, true}; }      // (low, high)
  static constexpr Range openClosed(double low, double high) { return {low, high, true, false}; }  // (low, high]
  static constexpr Range closedOpen(double low, double high) { return {low, high, false, true}; }  // [low, high)

  bool contains(double value) const {
    if (!std::isfinite(value)) return false;
    const bool above_low = low_open ? value > low : value >= low;
    const bool below_high = high_open ? value < high : value <= high;
    return above_low && below_high;
  }
  bool hasLow() const { return std::isfinite(low); }
  bool hasHigh() const { return std::isfinite(high); }
  // "must be in (0, 1] s", "must be >= 0", "must be finite"; `unit` "-" or empty is left out.
  std::string rule(const std::string& unit) const;

  static constexpr double kInf = std::numeric_limits<double>::infinity();
};

// Shortest text that reads back as the same double ("0.01", "1e-12", "100").
std::string shortestNumber(double value);

}  // namespace sdlqr
