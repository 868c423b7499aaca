// The one check of a path (path_check.hpp) judges a stop from every sample the path moves at, not
// only from its fastest: a GOTO or LAND may come anywhere along it.
#include <gtest/gtest.h>

#include "agile_vehicle.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/path_check.hpp"
#include "sdlqr/trajectory/sampling.hpp"

namespace sdlqr::trajectory {
namespace {


int movingSamplesOf(const Trajectory& path, const TransitionParams& params) {
  int moving = 0;
  for (const TrajectorySample& s : path.samples) moving += velocity(s.x).norm() > params.velocity_tolerance;
  return moving;
}

// GIVEN the paper's min-snap at 3 m/s (its start and corners slow and accelerating hard: no stop
// within 1.2 x their speed, Transition.AStopWhereThePathAcceleratesHardIsPlannedUnderThePathsSpeed)
// THEN a stop is found from each of its moving samples, and the check says so.
TEST(PathCheck, AStopIsFoundFromEveryMovingSampleOfThePapersMinSnap) {
  const TrajectoryParams params;
  const Trajectory minsnap = sampleTrajectory(paperMinSnapFast(params), params.sample_dt, kDefaultGravity);
  const LqrParams lqr;
  const TransitionParams transition;
  const PathCheck check = checkPath(minsnap, FeasibilityLimits::from(lqr, 6.0, params.accel_mismatch_max),
                                    position(minsnap.samples.front().x), 0.0, lqr, transition);
  EXPECT_TRUE(check.feasible()) << describePathCheck(check);
  EXPECT_EQ(check.exits_checked, movingSamplesOf(minsnap, transition));
  EXPECT_GT(check.exits_checked, 100);
  EXPECT_EQ(check.exits_missing, 0);
  const std::string text = describePathCheck(check);
  EXPECT_NE(text.find("exit: a stop from each of " + std::to_string(check.exits_checked) + " moving samples"),
            std::string::npos)
      << text;
}

// Negative: the agile lemniscate at 9 m/s on a vehicle of 40 m/s^2. Its samples are within the
// limits (39.4 m/s^2 at the most) and a stop from its fastest sample exists, which is all the check
// used to look at; from 11 samples pulling hard into its turns there is none. Refused, saying where.
TEST(PathCheck, APathWithNoStopFromSomeSampleIsRefusedThoughItsFastestHasOne) {
  const Trajectory lemniscate = test::agileLemniscate(9.0);
  LqrParams lqr = test::agileLqr(true);
  lqr.c_max = 40.0;
  const TransitionParams transition = test::agileTransitions();
  const PathCheck check = checkPath(lemniscate, FeasibilityLimits::from(lqr, 9.1, 0.5), Vec3(0, 0, 2), 0.0, lqr,
                                    transition);
  EXPECT_TRUE(check.samples.feasible());
  EXPECT_TRUE(planStop(flatStateOf(lemniscate.samples.front().x, lemniscate.samples.front().u, 0.0, kDefaultGravity), lqr,
                       transition, 9.0)
                  .found)
      << "from the fastest sample (the start, at the crossing)";
  EXPECT_FALSE(check.feasible());
  EXPECT_FALSE(check.exit.found);
  EXPECT_EQ(check.exits_checked, movingSamplesOf(lemniscate, transition));
  EXPECT_EQ(check.exits_missing, 11);
  EXPECT_NEAR(check.exit_from_t, 1.17, 0.05) << "the first sample without one, into the first turn";
  const std::string text = describePathCheck(check);
  EXPECT_NE(text.find("exit: no stop from 11 of 150 moving samples; from the first (1.1"), std::string::npos) << text;
}

}  // namespace
}  // namespace sdlqr::trajectory
