#include "sdlqr/config/range.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sdlqr {

std::string shortestNumber(double value) {
  char text[400];
  // Plain decimals where a person would write them (0.0005, 100), else scientific (2e-05, 1e+20).
  const double magnitude = std::fabs(value);
  const bool plain = value == 0.0 || (magnitude >= 1e-4 && magnitude < 1e15);
  // 17 significant digits always read back; a plain decimal below 1 needs its leading zeros too.
  for (int precision = 0; precision <= 17 + 4; ++precision) {
    std::snprintf(text, sizeof text, plain ? "%.*f" : "%.*e", precision, value);
    if (std::strtod(text, nullptr) == value) break;
  }
  return text;
}

std::string Range::rule(const std::string& unit) const {
  const std::string suffix = unit.empty() || unit == "-" ? "" : " " + unit;
  if (hasLow() && hasHigh()) {
    return "must be in " + std::string(low_open ? "(" : "[") + shortestNumber(low) + ", " + shortestNumber(high) +
           (high_open ? ")" : "]") + suffix;
  }
  if (hasLow()) return std::string("must be ") + (low_open ? "> " : ">= ") + shortestNumber(low) + suffix;
  if (hasHigh()) return std::string("must be ") + (high_open ? "< " : "<= ") + shortestNumber(high) + suffix;
  return "must be finite";
}

}  // namespace sdlqr
