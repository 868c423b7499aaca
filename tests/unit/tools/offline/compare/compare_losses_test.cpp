// "Where sdlqr is not the best": a better value counts only from a flight that failed no check
// sdlqr passed, and only beyond the margin; a crash or a sweep that goes faster is listed.
#include <gtest/gtest.h>

#include "sdlqr/compare/compare_losses.hpp"

namespace sdlqr::compare {
namespace {

analysis::Check check(const std::string& name, bool pass) {
  analysis::Check c;
  c.name = c.key = name;
  c.pass = pass;
  return c;
}

// A flight of experiment "e" with only a tilt to compare (every other metric does not apply).
ExperimentFlight flight(const std::string& controller, double tilt_deg, std::vector<analysis::Check> checks) {
  ExperimentFlight f;
  f.experiment = "e";
  f.controller = controller;
  f.report.max_tilt_deg = tilt_deg;
  f.report.checks = std::move(checks);
  return f;
}

CompareResult resultOf(std::vector<ExperimentFlight> flights) {
  CompareResult r;
  r.experiments.push_back({"e", "", "", 1});
  r.flights = std::move(flights);
  return r;
}

std::vector<std::string> tiltLosses(const CompareResult& r) {
  std::vector<std::string> out;
  for (const Loss& l : paperLosses(r)) {
    if (l.what == "max_tilt_deg [deg]") out.push_back(l.better + " " + l.value + " < " + l.paper);
  }
  return out;
}

TEST(PaperLosses, ABetterValueBeyondTheMarginIsListedWithTheBestController) {
  const CompareResult r = resultOf({flight("sdlqr", 40.0, {check("crashed", true)}),
                                    flight("geometric", 30.0, {check("crashed", true)}),
                                    flight("hover_lqr", 35.0, {check("crashed", true)})});
  EXPECT_EQ(tiltLosses(r), std::vector<std::string>{"geometric 30 < 40"});
}

TEST(PaperLosses, WithinTheMarginOrWorseNothingIsListed) {
  const CompareResult r = resultOf({flight("sdlqr", 40.0, {}), flight("geometric", 38.5, {}), flight("hover_lqr", 50.0, {})});
  EXPECT_TRUE(tiltLosses(r).empty());
}

TEST(PaperLosses, AFlightThatFailedACheckSdlqrPassedDoesNotCount) {
  const CompareResult r = resultOf({flight("sdlqr", 40.0, {check("crashed", true)}),
                                    flight("geometric", 10.0, {check("crashed", false)})});
  EXPECT_TRUE(tiltLosses(r).empty());
  EXPECT_FALSE(failsOnlyWhere(r.flights[1].report, r.flights[0].report));
  // Failing only where sdlqr fails too, it counts.
  const CompareResult both = resultOf({flight("sdlqr", 40.0, {check("crashed", false)}),
                                       flight("geometric", 10.0, {check("crashed", false)})});
  EXPECT_EQ(tiltLosses(both), std::vector<std::string>{"geometric 10 < 40"});
}

TEST(PaperLosses, AnExperimentSdlqrFailsThatAnotherPassesIsListed) {
  const CompareResult r = resultOf({flight("sdlqr", 40.0, {check("crashed", false)}),
                                    flight("geometric", 45.0, {check("crashed", true)})});
  const std::vector<Loss> losses = paperLosses(r);
  ASSERT_FALSE(losses.empty());
  EXPECT_EQ(losses[0].what, "every check");
  EXPECT_EQ(losses[0].paper, "fails crashed");
  EXPECT_EQ(losses[0].better, "geometric");
}

TEST(PaperLosses, ASweepThatFailsLaterOrNeverIsListed) {
  CompareResult r;
  r.sweeps.resize(3);
  r.sweeps[0].controller = "sdlqr";
  r.sweeps[0].first_failing_speed = 3.0;
  r.sweeps[1].controller = "geometric";
  r.sweeps[1].first_failing_speed = 2.5;
  r.sweeps[2].controller = "hover_lqr";  // never failed
  const std::vector<Loss> losses = paperLosses(r);
  ASSERT_EQ(losses.size(), 1u);
  EXPECT_EQ(losses[0].better, "hover_lqr");
  EXPECT_EQ(losses[0].value, "none");
  EXPECT_EQ(losses[0].paper, "3 m/s");
}

}  // namespace
}  // namespace sdlqr::compare
