#pragma once
// A flight report's check by name; a header, so the files of one test binary (one translation unit) share it.

#include <string>
#include "sdlqr/analysis/flight_report.hpp"

namespace sdlqr::test {

inline const analysis::Check* findCheck(const analysis::FlightReport& report, const std::string& name) {
  for (const analysis::Check& c : report.checks) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace sdlqr::test
