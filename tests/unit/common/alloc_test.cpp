// Zero heap allocation per gain solve, counted by the replaced operator new of tests/support.

#include <gtest/gtest.h>

#include <iostream>
#include <limits>
#include <random>
#include <vector>

#include "allocation_counter.hpp"
#include "sdlqr/math/lqr.hpp"
#include "sdlqr/math/quaternion.hpp"


namespace sdlqr {
namespace {

struct Point {
  State x;
  Input u;
};

std::vector<Point> drawPoints(int count) {
  std::mt19937_64 rng(99);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::vector<Point> points;
  for (int i = 0; i < count; ++i) {
    Vec3 omega(normal(rng), normal(rng), normal(rng));
    omega *= 10.0 * uniform(rng) / omega.norm();
    const Quat q = quat::exp(Vec3(normal(rng), normal(rng), normal(rng))) * (0.5 + uniform(rng));
    points.push_back({makeState(3.0 * Vec3(normal(rng), normal(rng), normal(rng)), q,
                                5.0 * Vec3(normal(rng), normal(rng), normal(rng))),
                      makeInput(omega, 2.0 + 16.0 * uniform(rng))});
  }
  return points;
}

TEST(LqrAllocation, TangentSolvesAllocateNothing) {
  const std::vector<Point> points = drawPoints(1000);
  const LqrParams params;
  int ok = 0;
  const long before = sdlqr::testing::allocationCount();
  for (const Point& p : points) ok += solveLqr(p.x, p.u, params).status == SolveStatus::kOk;
  const long allocations = sdlqr::testing::allocationCount() - before;
  std::cout << "1000 tangent solves: " << allocations << " allocations, " << ok << " ok\n";
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(ok, 1000);
}

TEST(LqrAllocation, IterativeAndFailingSolvesAllocateNothing) {
  // Invalid parameters are left out: LqrParams::invalidReason() formats its message into a
  // std::string; parameters are validated once when they change, not per solve.
  const std::vector<Point> points = drawPoints(20);
  LqrParams iterative;
  iterative.method = LqrMethod::kIterative;
  iterative.tolerance = 1e-9;
  LqrParams too_few_doublings;
  too_few_doublings.max_iterations = 2;
  State zero_q = points[0].x;
  orientation(zero_q).setZero();
  int statuses[4] = {0, 0, 0, 0};
  State nan_x = points[0].x;
  nan_x[kVel] = std::numeric_limits<double>::quiet_NaN();
  int finished = 0, not_converged = 0, rejected = 0;
  const long before = sdlqr::testing::allocationCount();
  for (const Point& p : points) {
    const LqrResult result = solveLqr(p.x, p.u, iterative);
    finished += result.iterations > 0;
    statuses[static_cast<int>(result.status)]++;
    not_converged += solveLqr(p.x, p.u, too_few_doublings).status == SolveStatus::kNotConverged;
  }
  rejected += solveLqr(zero_q, points[0].u, LqrParams()).status == SolveStatus::kInvalidInput;
  rejected += solveLqr(nan_x, points[0].u, LqrParams()).status == SolveStatus::kInvalidInput;
  const long allocations = sdlqr::testing::allocationCount() - before;
  std::cout << "20 iterative, 20 not converged, 2 rejected solves: " << allocations << " allocations\n";
  std::cout << "iterative statuses: " << statuses[0] << " ok, " << statuses[1] << " not converged, " << statuses[2]
            << " numerical failure\n";
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(finished, 20);
  EXPECT_EQ(not_converged, 20);
  EXPECT_EQ(rejected, 2);
}

TEST(LqrAllocation, CounterSeesAllocations) {
  // Guards the test itself: a vector push must be counted.
  EXPECT_GE(sdlqr::testing::allocationsOfOneVector(), 2);
}

}  // namespace
}  // namespace sdlqr
