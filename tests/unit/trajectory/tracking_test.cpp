#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "allocation_counter.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"
#include "sdlqr/trajectory/sampling.hpp"
#include "sdlqr/trajectory/tracking.hpp"


namespace sdlqr::trajectory {
namespace {

TrajectorySample sampleAt(double t, const Vec3& p, double yaw, double speed, double thrust) {
  TrajectorySample s;
  s.t = t;
  s.x = makeState(p, quat::fromYaw(yaw), Vec3(speed, 0.0, 0.0));
  s.u = makeInput(Vec3(0.1 * t, -0.2 * t, 0.3), thrust);
  return s;
}

// Five samples along x at 1 m spacing, one per second, each state and input different.
Trajectory straightLine() {
  Trajectory trajectory;
  for (int k = 0; k < 5; ++k) trajectory.samples.push_back(sampleAt(k, Vec3(k, 0.0, 1.0), 0.1 * k, k, 9.0 + k));
  return trajectory;
}

// A closed square: four corners and the closing sample.
Trajectory square() {
  Trajectory trajectory;
  trajectory.closed = true;
  const Vec3 corners[] = {Vec3(0, 0, 1), Vec3(1, 0, 1), Vec3(1, 1, 1), Vec3(0, 1, 1), Vec3(0, 0, 1)};
  for (int k = 0; k < 5; ++k) trajectory.samples.push_back(sampleAt(k, corners[k], 0.0, 1.0, 9.81));
  return trajectory;
}

// A copy tracks its own trajectory, in the active mode and from the place of the original (the
// replay tries an input on a copy of the controller): it outlives the original.
TEST(TrajectoryTrackerCopy, ContinuesFromTheOriginalsPlaceOnItsOwnTrajectory) {
  auto original = std::make_unique<TrajectoryTracker>();
  ASSERT_EQ(original->load(straightLine(), 0.0), "");
  original->update(0.0, Vec3(2.5, 0.0, 1.0));
  ASSERT_TRUE(original->setMode(ReferenceMode::kTemporal, 10.0));
  const TrajectoryTracker copy = *original;
  const TrackingOutput expected = original->update(10.5, Vec3::Zero());
  original.reset();
  TrajectoryTracker continued = copy;
  EXPECT_EQ(continued.mode(), ReferenceMode::kTemporal);
  const TrackingOutput out = continued.update(10.5, Vec3::Zero());
  EXPECT_EQ(out.index, expected.index);
  EXPECT_DOUBLE_EQ(out.time, expected.time);
  EXPECT_EQ(out.x, expected.x);
}

TEST(SpatialTracking, GammaIsTheProjectionOnTheSegment) {
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(straightLine(), 0.0), "");
  TrackingOutput out = tracker.update(0.0, Vec3(0.25, 0.3, 0.8));
  EXPECT_EQ(out.index, 1);
  EXPECT_DOUBLE_EQ(out.gamma, 0.25);
  out = tracker.update(0.0, Vec3(2.6, -1.0, 5.0));  // off the path: only the along-track part counts
  EXPECT_EQ(out.index, 3);
  EXPECT_NEAR(out.gamma, 0.6, 1e-15);
  EXPECT_NEAR(position(out.x).x(), 2.6, 1e-15);
  EXPECT_NEAR(out.time, 2.6, 1e-15);
}

TEST(SpatialTracking, InterpolatesWholeStateAndInput) {
  const Trajectory line = straightLine();
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(line, 0.0), "");
  const TrackingOutput out = tracker.update(0.0, Vec3(1.3, 0.0, 1.0));
  ASSERT_EQ(out.index, 2);
  const double g = out.gamma;
  ASSERT_NEAR(g, 0.3, 1e-15);
  const TrajectorySample& a = line.samples[1];
  const TrajectorySample& b = line.samples[2];
  EXPECT_LT((position(out.x) - (position(a.x) + g * (position(b.x) - position(a.x)))).norm(), 1e-15);
  EXPECT_LT((velocity(out.x) - (velocity(a.x) + g * (velocity(b.x) - velocity(a.x)))).norm(), 1e-15);
  EXPECT_LT((out.u - (a.u + g * (b.u - a.u))).norm(), 1e-15);
  const Quat lerp = (orientation(a.x) + g * (orientation(b.x) - orientation(a.x))).normalized();
  EXPECT_LT((orientation(out.x) - lerp).norm(), 1e-15);
  EXPECT_NEAR(orientation(out.x).norm(), 1.0, 1e-15);
}

TEST(SpatialTracking, InterpolatesQuaternionsInOneHemisphere) {
  Trajectory flipped = straightLine();
  orientation(flipped.samples[2].x) *= -1.0;  // same rotation, other sign
  TrajectorySample a = flipped.samples[1];
  TrajectorySample b = flipped.samples[2];
  TrackingOutput out;
  interpolateSamples(a, b, 0.5, out);
  // Without the hemisphere choice the mean of q and -q' would be near zero and meaningless.
  EXPECT_NEAR(quat::yaw(orientation(out.x)), 0.15, 1e-12);
  EXPECT_NEAR(orientation(out.x).norm(), 1.0, 1e-15);
}

TEST(SpatialTracking, IndexOnlyMovesForward) {
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(straightLine(), 0.0), "");
  EXPECT_EQ(tracker.update(0.0, Vec3(3.5, 0.0, 1.0)).index, 4);
  // Pulled back to the start: the reference waits at the last sample reached.
  for (double x = 3.4; x > -1.0; x -= 0.1) {
    const TrackingOutput out = tracker.update(0.0, Vec3(x, 0.0, 1.0));
    EXPECT_EQ(out.index, 4) << x;
    EXPECT_GE(out.gamma, 0.0);
    if (x < 3.0) {
      EXPECT_EQ(out.gamma, 0.0) << x;
      EXPECT_LT((position(out.x) - Vec3(3.0, 0.0, 1.0)).norm(), 1e-15) << x;
    }
  }
  // Released: it continues from there, without skipping.
  EXPECT_EQ(tracker.update(0.0, Vec3(3.2, 0.0, 1.0)).index, 4);
}

TEST(SpatialTracking, BehindTheStartHoldsTheFirstSample) {
  const Trajectory line = straightLine();
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(line, 0.0), "");
  const TrackingOutput out = tracker.update(0.0, Vec3(-2.0, 0.5, 1.0));  // raw gamma = -2
  EXPECT_EQ(out.index, 1);
  EXPECT_EQ(out.gamma, 0.0);
  EXPECT_LT((out.x - line.samples[0].x).norm(), 1e-15);
  EXPECT_LT((out.u - line.samples[0].u).norm(), 1e-15);
}

TEST(SpatialTracking, HoldsTheLastSampleAtTheEnd) {
  const Trajectory line = straightLine();
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(line, 0.0), "");
  const TrackingOutput out = tracker.update(0.0, Vec3(7.0, 0.0, 1.0));
  EXPECT_TRUE(out.finished);
  EXPECT_EQ(out.index, 4);
  EXPECT_EQ(out.gamma, 1.0);
  EXPECT_LT((out.x - line.samples[4].x).norm(), 1e-15);
  EXPECT_LT((out.u - line.samples[4].u).norm(), 1e-15);
  EXPECT_TRUE(tracker.update(0.0, Vec3(9.0, 0.0, 1.0)).finished);
}

TEST(SpatialTracking, SkipsZeroLengthSegments) {
  Trajectory stutter = straightLine();
  position(stutter.samples[2].x) = position(stutter.samples[1].x);  // samples 1 and 2 at x = 1
  SampleChecks two_metre_steps;
  two_metre_steps.max_position_jump = 2.0;
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(stutter, 0.0, two_metre_steps), "");
  TrackingOutput out = tracker.update(0.0, Vec3(2.0, 0.0, 1.0));  // segment 2 -> 3 runs from x = 1 to 3
  EXPECT_EQ(out.index, 3);
  EXPECT_NEAR(out.gamma, 0.5, 1e-15);
  // Exactly on the duplicated point: the reference is that point, with finite values.
  TrajectoryTracker at_point;
  ASSERT_EQ(at_point.load(stutter, 0.0, two_metre_steps), "");
  out = at_point.update(0.0, Vec3(1.0, 0.0, 1.0));
  EXPECT_TRUE(out.x.allFinite());
  EXPECT_NEAR(position(out.x).x(), 1.0, 1e-15);
}

TEST(SpatialTracking, CountsLapsOnAClosedTrajectory) {
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(square(), 0.0), "");
  const Vec3 route[] = {Vec3(0.5, 0, 1), Vec3(1, 0.5, 1), Vec3(0.5, 1, 1), Vec3(0, 0.5, 1)};
  int previous_index = 0;
  for (int lap = 0; lap < 3; ++lap) {
    for (int leg = 0; leg < 4; ++leg) {
      const TrackingOutput out = tracker.update(0.0, route[leg]);
      EXPECT_EQ(out.index, leg + 1);
      EXPECT_EQ(out.lap, lap);
      EXPECT_NEAR(out.gamma, 0.5, 1e-15);
      EXPECT_FALSE(out.finished);
      EXPECT_NEAR(out.time, lap * 4.0 + leg + 0.5, 1e-12);
      if (leg > 0) {
        EXPECT_GT(out.index, previous_index);
      }
      previous_index = out.index;
    }
  }
}

TEST(SpatialTracking, NonFinitePositionDoesNotAdvance) {
  const Trajectory line = straightLine();
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(line, 0.0), "");
  ASSERT_EQ(tracker.update(0.0, Vec3(1.5, 0.0, 1.0)).index, 2);
  for (const Vec3& bad : {Vec3(NAN, 0.0, 1.0), Vec3(INFINITY, 0.0, 1.0), Vec3(0.0, -INFINITY, 1.0)}) {
    const TrackingOutput out = tracker.update(0.0, bad);
    EXPECT_EQ(out.index, 2);
    EXPECT_EQ(out.gamma, 0.0);
    EXPECT_TRUE(out.x.allFinite());
  }
  EXPECT_EQ(tracker.update(0.0, Vec3(1.6, 0.0, 1.0)).index, 2);
}

TEST(SpatialTracking, DegenerateClosedPathDoesNotLoopForever) {
  Trajectory point = square();
  for (TrajectorySample& s : point.samples) position(s.x) = Vec3(0.0, 0.0, 1.0);  // every segment zero length
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(point, 0.0), "");
  const TrackingOutput out = tracker.update(0.0, Vec3(5.0, 0.0, 1.0));
  EXPECT_EQ(out.lap, 1);  // one lap per tick at most
  EXPECT_TRUE(out.x.allFinite());
}

TEST(TemporalTracking, ExactAtSampleTimesAndInterpolatedBetween) {
  const Trajectory line = straightLine();
  TrajectoryTracker tracker;
  Trajectory temporal = line;
  temporal.tracking = ReferenceMode::kTemporal;
  const double start = 100.0;
  ASSERT_EQ(tracker.load(temporal, start), "");
  EXPECT_EQ(tracker.mode(), ReferenceMode::kTemporal);
  for (int k = 0; k < 5; ++k) {
    const TrackingOutput out = tracker.update(start + k, Vec3(-9.0, 9.0, 9.0));  // position is ignored
    EXPECT_LT((out.x - line.samples[k].x).norm(), 1e-12) << k;
    EXPECT_LT((out.u - line.samples[k].u).norm(), 1e-12) << k;
  }
  const TrackingOutput mid = tracker.update(start + 2.25, Vec3::Zero());
  EXPECT_EQ(mid.index, 3);
  EXPECT_NEAR(mid.gamma, 0.25, 1e-12);
  EXPECT_NEAR(position(mid.x).x(), 2.25, 1e-12);
  EXPECT_NEAR(mid.u[kThrust], 11.25, 1e-12);
  // Before the start: the first sample; after the end: the last, finished.
  EXPECT_LT((tracker.update(start - 5.0, Vec3::Zero()).x - line.samples[0].x).norm(), 1e-15);
  const TrackingOutput after = tracker.update(start + 10.0, Vec3::Zero());
  EXPECT_TRUE(after.finished);
  EXPECT_LT((after.x - line.samples[4].x).norm(), 1e-15);
}

TEST(TemporalTracking, WrapsIntoLapsOnAClosedTrajectory) {
  Trajectory closed = square();
  closed.tracking = ReferenceMode::kTemporal;
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(closed, 0.0), "");
  const TrackingOutput out = tracker.update(2.0 * 4.0 + 1.5, Vec3::Zero());  // lap period 4 s
  EXPECT_EQ(out.lap, 2);
  EXPECT_EQ(out.index, 2);
  EXPECT_NEAR(out.gamma, 0.5, 1e-12);
  EXPECT_LT((position(out.x) - Vec3(1.0, 0.5, 1.0)).norm(), 1e-12);
  EXPECT_FALSE(out.finished);
}

TEST(ModeSwitch, SpatialToTemporalContinuesFromTheCurrentReference) {
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(straightLine(), 0.0), "");
  const TrackingOutput spatial = tracker.update(50.0, Vec3(1.4, 0.0, 1.0));  // far behind the clock
  ASSERT_TRUE(tracker.setMode(ReferenceMode::kTemporal, 50.0));
  const TrackingOutput same = tracker.update(50.0, Vec3(1.4, 0.0, 1.0));
  EXPECT_LT((same.x - spatial.x).norm(), 1e-12);  // no jump to t = 50 s (the end)
  const TrackingOutput later = tracker.update(50.5, Vec3::Zero());
  EXPECT_NEAR(position(later.x).x(), 1.9, 1e-12);  // then runs with the clock
}

TEST(ModeSwitch, TemporalToSpatialKeepsItsPlace) {
  Trajectory temporal = straightLine();
  temporal.tracking = ReferenceMode::kTemporal;
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(temporal, 0.0), "");
  EXPECT_EQ(tracker.update(3.2, Vec3::Zero()).index, 4);
  ASSERT_TRUE(tracker.setMode(ReferenceMode::kSpatial, 3.2));
  // The vehicle lags at x = 0.5; spatial tracking does not fall back to the start.
  const TrackingOutput out = tracker.update(3.3, Vec3(0.5, 0.0, 1.0));
  EXPECT_EQ(out.index, 4);
  EXPECT_FALSE(tracker.setMode(ReferenceMode::kSetpoint, 3.3));
  EXPECT_EQ(tracker.mode(), ReferenceMode::kSpatial);
}

TEST(TrajectoryTrackerLoad, RejectsInvalidAndKeepsThePrevious) {
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(straightLine(), 0.0), "");
  Trajectory backwards = square();
  backwards.samples[3].t = 1.5;
  EXPECT_EQ(tracker.load(backwards, 0.0), "sample 3: time not increasing");
  Trajectory open_ring = square();
  open_ring.samples.pop_back();
  EXPECT_NE(tracker.load(open_ring, 0.0).find("closed trajectory must end at its first position"), std::string::npos);
  Trajectory one = straightLine();
  one.samples.resize(1);
  EXPECT_EQ(tracker.load(one, 0.0), "fewer than 2 samples");
  EXPECT_TRUE(tracker.loaded());
  EXPECT_EQ(tracker.trajectory().samples.size(), 5u);
}

TEST(TrajectoryTrackerLoad, UpdateAllocatesNothing) {
  const Trajectory fast = sampleTrajectory(paperMinSnapFast(TrajectoryParams{}), 0.1, 9.81);
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(fast, 0.0), "");
  const sdlqr::testing::AllocationCounter allocations;
  for (int tick = 0; tick < 2000; ++tick) {
    const double t = tick * 0.01;
    if (tick == 1000) tracker.setMode(ReferenceMode::kTemporal, t);
    const TrackingOutput out = tracker.update(t, position(fast.samples[std::min<std::size_t>(tick / 10, 110)].x));
    ASSERT_TRUE(out.x.allFinite());
  }
  EXPECT_EQ(allocations.count(), 0);
}

TEST(TrajectoryTrackerLoad, PaperDisturbanceHeldVehicleResumesWithoutSkipping) {
  // §III-C.4: the vehicle is held still mid-trajectory, then released and flown along the path.
  const Trajectory slow = sampleTrajectory(paperMinSnapSlow(TrajectoryParams{}), 0.1, 9.81);
  TrajectoryTracker tracker;
  ASSERT_EQ(tracker.load(slow, 0.0), "");
  for (int k = 0; k < 60; ++k) tracker.update(0.0, position(slow.samples[k].x));
  const Vec3 held = position(slow.samples[60].x);
  const int first_held_index = tracker.update(0.0, held).index;
  for (int tick = 0; tick < 500; ++tick) EXPECT_EQ(tracker.update(0.0, held).index, first_held_index);
  const int held_index = tracker.lastReference().index;
  for (int k = 61; k < 120; ++k) {
    const int now = tracker.update(0.0, position(slow.samples[k].x)).index;
    EXPECT_LE(now, k + 1);  // never ahead of the vehicle: no segment skipped
    EXPECT_GE(now, held_index);
  }
}

}  // namespace
}  // namespace sdlqr::trajectory
