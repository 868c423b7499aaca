#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>

#include "sdlqr/math/model.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/flatness.hpp"
#include "sdlqr/trajectory/paper_cases.hpp"

namespace sdlqr::trajectory {
namespace {

// Flies the feed-forward inputs open loop through the paper's model (RK4, inputs taken from the
// flat map at each stage time) and returns the largest position error over [t0, t0 + span].
// With `plant_drag` the model flown has rotor drag, and `feed_forward_drag` is the drag the flat map
// compensates.
double openLoopDrift(const MinSnapTrajectory& trajectory, double t0, double span, double* attitude_error = nullptr,
                     const RotorDrag& plant_drag = {}, const RotorDrag& feed_forward_drag = {}) {
  const double h = 1e-3;
  auto reference = [&](double t) { return flatToReference(trajectory.evaluate(t), kDefaultGravity, feed_forward_drag); };
  auto input = [&](double t) { return reference(t).u; };
  auto dynamics = [&](const State& x, const Input& u, double g) { return sdlqr::dynamics(x, u, g, plant_drag); };
  State x = reference(t0).x;
  double worst = 0.0;
  double worst_attitude = 0.0;
  const int steps = static_cast<int>(std::lround(span / h));
  for (int i = 0; i < steps; ++i) {
    const double t = t0 + i * h;
    const State k1 = dynamics(x, input(t), kDefaultGravity);
    const State k2 = dynamics(x + 0.5 * h * k1, input(t + 0.5 * h), kDefaultGravity);
    const State k3 = dynamics(x + 0.5 * h * k2, input(t + 0.5 * h), kDefaultGravity);
    const State k4 = dynamics(x + h * k3, input(t + h), kDefaultGravity);
    x += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    orientation(x).normalize();
    const State target = reference(t + h).x;
    worst = std::max(worst, (position(x) - position(target)).norm());
    worst_attitude = std::max(worst_attitude, quat::boxMinus(orientation(x), orientation(target)).norm());
  }
  if (attitude_error) *attitude_error = worst_attitude;
  return worst;
}

TEST(Flatness, FeedForwardReproducesTheSlowPaperTrajectoryOpenLoop) {
  const MinSnapTrajectory slow = paperMinSnapSlow(TrajectoryParams{});
  double attitude = 0.0;
  const double drift = openLoopDrift(slow, 0.0, 5.0, &attitude);
  std::cout << "  slow (1 m/s): open-loop position drift over 5 s " << drift * 1e3 << " mm, attitude "
            << attitude << " rad\n";
  EXPECT_LT(drift, 0.01);
  RecordProperty("slow_drift_m", std::to_string(drift));
}

TEST(Flatness, FeedForwardReproducesTheFastPaperTrajectoryOpenLoop) {
  const MinSnapTrajectory fast = paperMinSnapFast(TrajectoryParams{});
  double attitude = 0.0;
  const double drift = openLoopDrift(fast, 0.0, 5.0, &attitude);
  // Over the middle of the flight too, where speed and body rates are largest.
  const double drift_middle = openLoopDrift(fast, 0.5 * fast.duration() - 2.5, 5.0);
  std::cout << "  fast (3 m/s): open-loop position drift over 5 s from the start " << drift * 1e3
            << " mm (attitude " << attitude << " rad), mid-flight " << drift_middle * 1e3 << " mm\n";
  RecordProperty("fast_drift_m", std::to_string(std::max(drift, drift_middle)));
  EXPECT_LT(drift, 0.01);
  EXPECT_LT(drift_middle, 0.01);
}

TEST(Flatness, YawRateFeedForwardIsExactToo) {
  // A turning heading exercises omega_z, which the paper's trajectories (fixed yaw) do not.
  std::vector<Waypoint> waypoints = paperWaypoints(1.0);
  const double yaws[] = {0.0, 1.5, 3.0, -1.5};
  for (int j = 0; j < 4; ++j) {
    waypoints[j].yaw = yaws[j];
    waypoints[j].has_yaw = true;
  }
  MinSnapOptions options;
  options.v_max = 2.0;
  options.periodic = true;
  const MinSnapTrajectory lap = generateMinSnap(waypoints, options);
  double attitude = 0.0;
  const double drift = openLoopDrift(lap, 0.0, 5.0, &attitude);
  std::cout << "  turning heading (2 m/s, periodic): drift over 5 s " << drift * 1e3 << " mm, attitude " << attitude
            << " rad\n";
  EXPECT_LT(drift, 0.01);
  EXPECT_LT(attitude, 1e-4);
}

// Min-snap through the paper's waypoints, heading yaw_step * j at waypoint j.
MinSnapTrajectory turningMinSnap(double yaw_step, double v_max, bool periodic) {
  std::vector<Waypoint> waypoints = paperWaypoints(1.0);
  for (int j = 0; j < 4; ++j) {
    waypoints[j].yaw = yaw_step * j;
    waypoints[j].has_yaw = true;
  }
  MinSnapOptions options;
  options.v_max = v_max;
  options.periodic = periodic;
  return generateMinSnap(waypoints, options);
}

// A lap at 5 m/s with a turning heading (the agile vehicle's scaled min-snap speed).
MinSnapTrajectory fastTurningLap() { return turningMinSnap(0.8, 5.0, true); }

RotorDrag agileDrag() {
  RotorDrag drag;
  drag.coefficients = Vec3(0.69, 0.69, 1.34);  // config/agile752.yaml
  return drag;
}

// Issue 25: the feed-forward with rotor drag flies the path open loop through the model with the
// same drag (the attitude, thrust and body rates that realize a + g plus the drag v causes);
// the drag-free feed-forward through that model leaves it by metres (the negative).
TEST(Flatness, RotorDragFeedForwardReproducesAFastLapOpenLoopThroughTheDragModel) {
  const MinSnapTrajectory lap = fastTurningLap();
  double attitude = 0.0;
  const double drift = openLoopDrift(lap, 0.0, 5.0, &attitude, agileDrag(), agileDrag());
  const double uncompensated = openLoopDrift(lap, 0.0, 5.0, nullptr, agileDrag(), RotorDrag{});
  std::cout << "  5 m/s lap with drag 0.69/0.69/1.34 1/s: open-loop drift over 5 s " << drift * 1e3
            << " mm (attitude " << attitude << " rad); drag-free feed-forward " << uncompensated << " m\n";
  EXPECT_LT(drift, 0.01);
  EXPECT_LT(attitude, 1e-3);
  EXPECT_GT(uncompensated, 1.0);
}

// The thrust vector with drag: c z_b = a + g e_z + s(c) R D R^T v (so f's velocity row is a exactly),
// body rates the attitude's derivative, and no drag is the map above bit for bit.
TEST(Flatness, RotorDragReferenceBalancesTheDragAndItsRatesMatchTheAttitude) {
  const MinSnapTrajectory lap = fastTurningLap();
  const double h = 1e-5;
  double worst_rate = 0.0;
  for (double t = 0.1; t < lap.duration() - 0.1; t += 0.1) {
    const FlatOutput flat = lap.evaluate(t);
    const FlatReference ref = flatToReference(flat, kDefaultGravity, agileDrag());
    ASSERT_FALSE(ref.singular);
    const State f = dynamics(ref.x, ref.u, kDefaultGravity, agileDrag());
    EXPECT_LT((velocity(f) - flat.acceleration).norm(), 1e-9) << "t " << t;
    // The heading's construction: x_b perpendicular to y_c (ZYX yaw flips where the tilt passes 90 degrees).
    const Vec3 y_c(-std::sin(flat.yaw), std::cos(flat.yaw), 0.0);
    EXPECT_NEAR(quat::rotationMatrix(orientation(ref.x)).col(0).dot(y_c), 0.0, 1e-12);
    const Quat before = orientation(flatToReference(lap.evaluate(t - h), kDefaultGravity, agileDrag()).x);
    const Quat after = orientation(flatToReference(lap.evaluate(t + h), kDefaultGravity, agileDrag()).x);
    worst_rate = std::max(worst_rate, (quat::boxMinus(after, before) / (2.0 * h) - bodyRate(ref.u)).norm());
    const FlatReference none = flatToReference(flat, kDefaultGravity, RotorDrag{});
    const FlatReference paper = flatToReference(flat, kDefaultGravity);
    EXPECT_EQ(none.x, paper.x);
    EXPECT_EQ(none.u, paper.u);
  }
  std::cout << "  with drag: largest body-rate error against the attitude's finite difference " << worst_rate
            << " rad/s\n";
  EXPECT_LT(worst_rate, 1e-5);
}

TEST(Flatness, AttitudeAndThrustMatchAccelerationPlusGravity) {
  const MinSnapTrajectory trajectory = turningMinSnap(0.7, 3.0, false);
  for (double t = 0.0; t < trajectory.duration(); t += 0.05) {
    const FlatOutput flat = trajectory.evaluate(t);
    const FlatReference ref = flatToReference(flat, kDefaultGravity);
    ASSERT_FALSE(ref.singular);
    const Vec3 thrust_vector = flat.acceleration + Vec3(0.0, 0.0, kDefaultGravity);
    EXPECT_NEAR(ref.u[kThrust], thrust_vector.norm(), 1e-12);
    EXPECT_LT((ref.u[kThrust] * quat::bodyZ(orientation(ref.x)) - thrust_vector).norm(), 1e-12);
    EXPECT_NEAR(std::remainder(quat::yaw(orientation(ref.x)) - flat.yaw, 2 * M_PI), 0.0, 1e-12);
    EXPECT_NEAR(orientation(ref.x).norm(), 1.0, 1e-14);
    EXPECT_LT((position(ref.x) - flat.position).norm(), 1e-15);
    EXPECT_LT((velocity(ref.x) - flat.velocity).norm(), 1e-15);
  }
}

TEST(Flatness, BodyRatesMatchTheAttitudeDerivative) {
  // q' = 1/2 q (x) [0, omega]: compare with a central difference of the flat attitude.
  std::vector<Waypoint> waypoints = paperWaypoints(1.0);
  for (int j = 0; j < 4; ++j) {
    waypoints[j].yaw = -0.9 * j;
    waypoints[j].has_yaw = true;
  }
  MinSnapOptions options;
  options.v_max = 3.0;
  const MinSnapTrajectory trajectory = generateMinSnap(waypoints, options);
  const double h = 1e-5;
  double worst = 0.0;
  for (double t = 0.1; t < trajectory.duration() - 0.1; t += 0.1) {
    const Quat before = orientation(flatToReference(trajectory.evaluate(t - h), kDefaultGravity).x);
    const Quat after = orientation(flatToReference(trajectory.evaluate(t + h), kDefaultGravity).x);
    const Vec3 measured = quat::boxMinus(after, before) / (2.0 * h);
    const Vec3 omega = bodyRate(flatToReference(trajectory.evaluate(t), kDefaultGravity).u);
    worst = std::max(worst, (measured - omega).norm());
  }
  std::cout << "  largest body-rate error against the attitude's finite difference " << worst << " rad/s\n";
  EXPECT_LT(worst, 1e-6);
}

TEST(Flatness, HoverIsLevelWithHoverThrust) {
  FlatOutput hover;
  hover.position = Vec3(1, 2, 3);
  hover.yaw = 0.4;
  const FlatReference ref = flatToReference(hover, kDefaultGravity);
  EXPECT_NEAR(ref.u[kThrust], kDefaultGravity, 1e-15);
  EXPECT_LT(bodyRate(ref.u).norm(), 1e-15);
  EXPECT_LT((orientation(ref.x) - quat::fromYaw(0.4)).norm(), 1e-15);
}

TEST(Flatness, FreeFallIsFlaggedSingular) {
  FlatOutput falling;
  falling.acceleration = Vec3(0.0, 0.0, -kDefaultGravity);
  falling.jerk = Vec3(1.0, 0.0, 0.0);
  const FlatReference ref = flatToReference(falling, kDefaultGravity);
  EXPECT_TRUE(ref.singular);
  EXPECT_TRUE(ref.x.allFinite());
  EXPECT_TRUE(ref.u.allFinite());
}

TEST(Flatness, QuaternionFromRotationInvertsRotationMatrix) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int i = 0; i < 100; ++i) {
    Quat q(n(rng), n(rng), n(rng), n(rng));
    q.normalize();
    const Quat back = quaternionFromRotation(quat::rotationMatrix(q));
    EXPECT_LT((back - quat::sameHemisphere(q, back)).norm(), 1e-12);
    EXPECT_GE(back[0], 0.0);
  }
}

}  // namespace
}  // namespace sdlqr::trajectory
