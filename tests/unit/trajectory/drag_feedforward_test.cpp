// The controller's feed-forward (and what the feasibility check judges) against the model's rotor drag (drag_feedforward.hpp, issue 25).
#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/trajectory/drag_feedforward.hpp"
#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/trajectory/flatness.hpp"

namespace sdlqr::trajectory::feedforward_test {
namespace {

constexpr double kG = 9.81;

RotorDrag agileDrag() {
  RotorDrag drag;
  drag.coefficients = Vec3(0.69, 0.69, 1.34);  // config/agile752.yaml
  drag.gravity = kG;
  return drag;
}

// A point of a level 3 m circle at 8 m/s (its thrust is constant: the jerk lies across z_b, the
// case where the reference's missing thrust rate is exactly zero), heading turning with it.
FlatOutput circlePoint(double angle) {
  const double radius = 3.0, speed = 8.0, rate = speed / radius;
  FlatOutput flat;
  flat.position = Vec3(radius * std::cos(angle), radius * std::sin(angle), 2.0);
  flat.velocity = speed * Vec3(-std::sin(angle), std::cos(angle), 0.0);
  flat.acceleration = -speed * rate * Vec3(std::cos(angle), std::sin(angle), 0.0);
  flat.jerk = speed * rate * rate * Vec3(std::sin(angle), -std::cos(angle), 0.0);
  flat.yaw = angle;
  flat.yaw_rate = rate;
  return flat;
}

// GIVEN the drag-free reference of a fast circle WHEN remapped against the drag THEN the model with
// drag accelerates as the path asks, position and velocity are kept, and attitude, thrust and body
// rates are those of the flat map with drag.
TEST(DragFeedForward, TheRemappedReferenceFliesThePathThroughTheModelWithDrag) {
  for (double angle : {0.0, 1.0, 2.5, -2.0}) {
    const FlatOutput flat = circlePoint(angle);
    const FlatReference drag_free = flatToReference(flat, kG);
    State x = drag_free.x;
    Input u = drag_free.u;
    compensateRotorDrag(x, u, kG, agileDrag());
    const State f = dynamics(x, u, kG, agileDrag());
    EXPECT_LT((velocity(f) - flat.acceleration).norm(), 1e-9) << "angle " << angle;
    EXPECT_EQ(position(x), position(drag_free.x));
    EXPECT_EQ(velocity(x), velocity(drag_free.x));
    const FlatReference expected = flatToReference(flat, kG, agileDrag());
    EXPECT_LT(quat::boxMinus(orientation(x), orientation(expected.x)).norm(), 1e-9);
    EXPECT_LT((u - expected.u).norm(), 1e-8) << "angle " << angle << ": " << u.transpose() << " vs "
                                             << expected.u.transpose();
    // The drag is not small here: the drag-free thrust misses it by metres per second squared.
    EXPECT_GT((velocity(dynamics(drag_free.x, drag_free.u, kG, agileDrag())) - flat.acceleration).norm(), 3.0);
  }
}

// No drag (lqr.model_rotor_drag off): the reference is left as it was, bit for bit.
TEST(DragFeedForward, WithoutDragTheReferenceIsUnchanged) {
  const FlatReference drag_free = flatToReference(circlePoint(0.7), kG);
  State x = drag_free.x;
  Input u = drag_free.u;
  compensateRotorDrag(x, u, kG, RotorDrag{});
  EXPECT_EQ(x, drag_free.x);
  EXPECT_EQ(u, drag_free.u);
}

}  // namespace
}  // namespace sdlqr::trajectory::feedforward_test
