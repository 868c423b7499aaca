#pragma once
// Where the paper's controller (sdlqr) is not the best in a comparison: every experiment and
// metric where another controller is more than kLossMargin lower (better), counting only
// controllers that failed no check sdlqr passed (a flight that crashed or never finished its
// trajectory has small errors for a reason that is no merit); every experiment sdlqr fails that
// another passes; every controller whose speed sweep first fails at a higher speed.

#include <string>
#include <vector>

#include "sdlqr/compare/compare_run.hpp"

namespace sdlqr::compare {

// The controller a comparison measures the others against.
inline constexpr const char* kPaperController = "sdlqr";
// 5 %: the rounding noise of near-identical flights is not listed.
inline constexpr double kLossMargin = 0.05;

struct Loss {
  std::string experiment;  // or kSweepName
  std::string what;        // "max_tilt_deg [deg]", "every check", "first failing speed"
  std::string paper;       // sdlqr's value as the report prints it
  std::string better;      // the better controller(s)
  std::string value;       // its value as the report prints it
};

std::vector<Loss> paperLosses(const CompareResult& result);

// True when `other` failed no check that `reference` passed.
bool failsOnlyWhere(const analysis::FlightReport& other, const analysis::FlightReport& reference);

}  // namespace sdlqr::compare
