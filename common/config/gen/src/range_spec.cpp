// The range syntax of a declaration file, mapped onto the Range:: factories of
// sdlqr/config/range.hpp: "finite", "> a", ">= a", "[a, b]", "(a, b)", "(a, b]", "[a, b)".

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "sdlqr/paramgen/declaration.hpp"

namespace sdlqr::paramgen {

namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(' ');
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(' ') - first + 1);
}

// A bound: a number literal, kept as written for the C++.
double bound(const std::string& text, const std::string& range) {
  char* end = nullptr;
  const double value = text.empty() ? NAN : std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(value)) {
    throw std::invalid_argument("bad range \"" + range + "\": '" + text + "' is not a finite number");
  }
  return value;
}

RangeSpec interval(const std::string& text) {
  const char open = text.front();
  const char close = text.back();
  const auto comma = text.find(',');
  if ((open != '[' && open != '(') || (close != ']' && close != ')') || comma == std::string::npos) {
    throw std::invalid_argument("bad range \"" + text + "\": expected finite, > a, >= a or an interval like (a, b]");
  }
  RangeSpec r;
  r.low_text = trimmed(text.substr(1, comma - 1));
  r.high_text = trimmed(text.substr(comma + 1, text.size() - comma - 2));
  r.low = bound(r.low_text, text);
  r.high = bound(r.high_text, text);
  r.has_low = r.has_high = true;
  r.low_open = open == '(';
  r.high_open = close == ')';
  if (!(r.low < r.high)) throw std::invalid_argument("bad range \"" + text + "\": the low end must be below the high end");
  r.factory = r.low_open ? (r.high_open ? "open" : "openClosed") : (r.high_open ? "closedOpen" : "closed");
  return r;
}

}  // namespace

RangeSpec parseRange(const std::string& raw) {
  const std::string text = trimmed(raw);
  if (text == "finite") return {};
  if (text.rfind(">=", 0) == 0 || text.rfind(">", 0) == 0) {
    const bool inclusive = text.rfind(">=", 0) == 0;
    RangeSpec r;
    r.low_text = trimmed(text.substr(inclusive ? 2 : 1));
    r.low = bound(r.low_text, text);
    r.has_low = true;
    r.low_open = !inclusive;
    r.factory = inclusive ? "atLeast" : "above";
    return r;
  }
  if (text.empty()) throw std::invalid_argument("bad range \"\": expected finite, > a, >= a or an interval like (a, b]");
  return interval(text);
}

bool RangeSpec::contains(double value) const {
  if (!std::isfinite(value)) return false;
  const bool above_low = !has_low || (low_open ? value > low : value >= low);
  const bool below_high = !has_high || (high_open ? value < high : value <= high);
  return above_low && below_high;
}

std::string RangeSpec::cpp() const {
  std::string args = low_text;
  if (has_high) args += ", " + high_text;
  return "Range::" + factory + "(" + args + ")";
}

}  // namespace sdlqr::paramgen
