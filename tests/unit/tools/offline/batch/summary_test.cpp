// Wilson intervals against values computed by hand, and the summary's worst flights.
#include <gtest/gtest.h>

#include "sdlqr/batch/summary.hpp"

namespace sdlqr::batch {
namespace {

TEST(Wilson, MatchesTheClosedForm) {
  // p = 0.5, n = 10, z = 1.96: centre 0.5, half 0.2634.
  const Interval half = wilson(5, 10);
  EXPECT_NEAR(half.low, 0.2366, 1e-4);
  EXPECT_NEAR(half.high, 0.7634, 1e-4);
  // No success in 10: [0, z^2 / (n + z^2)] = [0, 0.2775].
  const Interval none = wilson(0, 10);
  EXPECT_DOUBLE_EQ(none.low, 0.0);
  EXPECT_NEAR(none.high, 0.2775, 1e-4);
  // All of 1000: the lower end 0.99617.
  EXPECT_NEAR(wilson(1000, 1000).low, 0.99617, 1e-5);
  EXPECT_DOUBLE_EQ(wilson(0, 0).high, 1.0);
}

TEST(Summary, WorstFlightsAreTheFailedOnesMostFailuresFirst) {
  Table t;
  t.header = {"flight", "controller", "seed", "pass", "failed_checks", "max_tilt_deg"};
  t.rows = {{"0", "sdlqr", "1", "1", "0", "5"},
            {"1", "sdlqr", "2", "0", "1", "9"},
            {"2", "sdlqr", "3", "0", "3", "2"},
            {"3", "sdlqr", "4", "0", "1", "20"}};
  EXPECT_EQ(worstRows(t, 5), (std::vector<size_t>{2, 3, 1}));
  EXPECT_EQ(worstRows(t, 1), (std::vector<size_t>{2}));
}

}  // namespace
}  // namespace sdlqr::batch
