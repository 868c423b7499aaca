// Frames and signs (px4/frames.hpp): every conversion pinned with cases computed by hand, so a
// sign error cannot fly. PX4: NED world, FRD body, q rotates FRD into NED. sdlqr: world z up
// (x east, y north as ENU), body x front, y left, z up (the thrust axis).

#include <gtest/gtest.h>

#include <cmath>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/px4/estimate_messages.hpp"
#include "sdlqr/px4/frames.hpp"

namespace sdlqr::px4 {
namespace {

constexpr double kDeg = M_PI / 180.0;

void expectNear(const Vec3& a, const Vec3& b, double tol = 1e-12) {
  EXPECT_NEAR(a[0], b[0], tol);
  EXPECT_NEAR(a[1], b[1], tol);
  EXPECT_NEAR(a[2], b[2], tol);
}

// q with its sign chosen so that w >= 0 (q and -q are the same attitude).
Quat canonical(const Quat& q) { return q[0] < 0.0 ? Quat(-q) : q; }

TEST(Px4Frames, AClimbIsUpInTheWorldAndDownwardNegativeInNed) {
  // 2 m above the origin, climbing at 1 m/s, 3 m north and 1 m east.
  const Vec3 p_ned(3.0, 1.0, -2.0), v_ned(0.0, 0.0, -1.0);
  expectNear(nedToWorld(p_ned), Vec3(1.0, 3.0, 2.0));
  expectNear(nedToWorld(v_ned), Vec3(0.0, 0.0, 1.0));
  expectNear(worldToNed(nedToWorld(p_ned)), p_ned);
}

TEST(Px4Frames, LevelFacingNorthIsAYawOf90DegreesInTheWorld) {
  // PX4's identity: nose north, level. North is sdlqr's +y: a yaw of +90 deg about z up.
  const Quat q = nedFrdToWorldBody(identityQuat());
  EXPECT_NEAR(quat::yaw(q), 90.0 * kDeg, 1e-12);
  expectNear(quat::rotate(q, Vec3::UnitX()), Vec3::UnitY());      // nose north
  expectNear(quat::rotate(q, Vec3::UnitZ()), Vec3::UnitZ());      // thrust up
  expectNear(quat::rotate(q, Vec3::UnitY()), -Vec3::UnitX());     // left wing west
}

TEST(Px4Frames, AYawOf90DegreesInNedFacesEastWhichIsTheWorldsX) {
  const Quat q_ned(std::cos(45 * kDeg), 0.0, 0.0, std::sin(45 * kDeg));  // nose east
  const Quat q = canonical(nedFrdToWorldBody(q_ned));
  EXPECT_NEAR(q[0], 1.0, 1e-12);  // sdlqr's identity: x (east) forward
  EXPECT_NEAR(quat::yaw(q), 0.0, 1e-12);
  // yaw_world = 90 deg - yaw_NED over a range of headings.
  for (double yaw_ned = -170.0; yaw_ned <= 170.0; yaw_ned += 20.0) {
    const Quat qn(std::cos(0.5 * yaw_ned * kDeg), 0.0, 0.0, std::sin(0.5 * yaw_ned * kDeg));
    const double yaw = quat::yaw(nedFrdToWorldBody(qn)) / kDeg;
    EXPECT_NEAR(std::remainder(yaw - (90.0 - yaw_ned), 360.0), 0.0, 1e-9) << yaw_ned;
  }
}

TEST(Px4Frames, ARollOf30DegreesRightPutsTheLeftWingUpAndWest) {
  // Nose north, rolled 30 deg right (right wing down) about FRD x.
  const Quat q_ned(std::cos(15 * kDeg), std::sin(15 * kDeg), 0.0, 0.0);
  const Quat q = nedFrdToWorldBody(q_ned);
  // By hand: FRD right wing in NED (0, cos30, sin30): east and down; in the world (cos30, 0, -sin30).
  // sdlqr's left wing is its opposite: west and up.
  expectNear(quat::rotate(q, Vec3::UnitY()), Vec3(-std::cos(30 * kDeg), 0.0, std::sin(30 * kDeg)));
  // The thrust axis leans to the right (east): (sin30, 0, cos30).
  expectNear(quat::rotate(q, Vec3::UnitZ()), Vec3(std::sin(30 * kDeg), 0.0, std::cos(30 * kDeg)));
  EXPECT_NEAR(quat::tilt(q), 30.0 * kDeg, 1e-12);
  // The same vectors through PX4's own rotation and the fixed axis swaps agree.
  const Vec3 right_ned = quat::rotate(q_ned, Vec3::UnitY());
  expectNear(nedToWorld(right_ned), quat::rotate(q, frdToBody(Vec3::UnitY())));
}

TEST(Px4Frames, BodyRatesAndVectorsFlipYAndZ) {
  // Nose up (FRD pitch rate +), roll right (+), yaw right (+, clockwise seen from above):
  // in sdlqr's body: roll +, pitch - (about the left axis), yaw - (about z up).
  expectNear(frdToBody(Vec3(0.1, 0.2, 0.3)), Vec3(0.1, -0.2, -0.3));
  expectNear(bodyToFrd(frdToBody(Vec3(0.1, 0.2, 0.3))), Vec3(0.1, 0.2, 0.3));
  // Thrust along sdlqr's +z is along FRD -z (PX4: thrust_body[2] = -thrust).
  expectNear(bodyToFrd(Vec3(0.0, 0.0, 9.81)), Vec3(0.0, 0.0, -9.81));
}

TEST(Px4Frames, AttitudeMapsBackExactlyAndAgreesWithRotationMatrices) {
  const Quat q_ned = quat::exp(Vec3(0.3, -0.2, 1.1));
  const Quat back = worldBodyToNedFrd(nedFrdToWorldBody(q_ned));
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(back[i], q_ned[i], 1e-12);
  // R_world_body = P R_ned_frd F with P the NED->world swap and F the body->FRD flip.
  Mat3 P, F;
  P << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  F << 1, 0, 0, 0, -1, 0, 0, 0, -1;
  const Mat3 expected = P * quat::rotationMatrix(q_ned) * F;
  const Mat3 actual = quat::rotationMatrix(nedFrdToWorldBody(q_ned));
  EXPECT_LT((expected - actual).norm(), 1e-12);
}

TEST(Px4Frames, OdometryOfAClimbingRolledVehicleBecomesTheSameStateEstimate) {
  StateEstimate e;
  e.utime = 12'340'000;
  e.position = Vec3(1.0, 3.0, 2.0);
  e.velocity = Vec3(0.0, 0.5, 1.0);
  e.orientation = nedFrdToWorldBody(Quat(std::cos(15 * kDeg), std::sin(15 * kDeg), 0.0, 0.0));
  e.body_rate = Vec3(0.1, -0.2, 0.3);
  e.position_std = Vec3(0.01, 0.02, 0.03);
  const mavlink::Odometry m = odometryFromEstimate(e);
  EXPECT_FLOAT_EQ(m.x, 3.0f);   // north
  EXPECT_FLOAT_EQ(m.y, 1.0f);   // east
  EXPECT_FLOAT_EQ(m.z, -2.0f);  // 2 m up
  EXPECT_FLOAT_EQ(m.vz, -1.0f);
  EXPECT_FLOAT_EQ(m.pitchspeed, 0.2f);
  EXPECT_NEAR(m.q[1], std::sin(15 * kDeg), 1e-7);
  RejectReason reason = RejectReason::kNone;
  const StateEstimate back = estimateFromOdometry(m, &reason);
  EXPECT_EQ(reason, RejectReason::kNone);
  EXPECT_EQ(back.utime, e.utime);
  EXPECT_LT((back.position - e.position).norm(), 1e-6);
  EXPECT_LT((back.velocity - e.velocity).norm(), 1e-6);
  EXPECT_LT((back.orientation - e.orientation).norm(), 1e-6);
  EXPECT_LT((back.body_rate - e.body_rate).norm(), 1e-6);
  EXPECT_LT((back.position_std - e.position_std).norm(), 1e-6);
}

TEST(Px4Frames, OdometryWithVelocityInTheBodyFrameIsRotatedIntoTheWorld) {
  mavlink::Odometry m;
  m.frame_id = mavlink::mav_frame::kLocalNed;
  m.child_frame_id = mavlink::mav_frame::kBodyFrd;
  m.q = {std::cos(0.25f * static_cast<float>(M_PI)), 0.0f, 0.0f, std::sin(0.25f * static_cast<float>(M_PI))};  // east
  m.vx = 2.0f;  // forward
  RejectReason reason = RejectReason::kNone;
  const StateEstimate e = estimateFromOdometry(m, &reason);
  EXPECT_EQ(reason, RejectReason::kNone);
  expectNear(e.velocity, Vec3(2.0, 0.0, 0.0), 1e-6);  // east is the world's x
  m.child_frame_id = mavlink::mav_frame::kGlobal;
  estimateFromOdometry(m, &reason);
  EXPECT_EQ(reason, RejectReason::kBadEnum);
}

TEST(Px4Frames, HighresImuAtRestReadsMinusGravityDownInFrdAndUpInTheBody) {
  mavlink::HighresImu m;
  m.zacc = -9.81f;  // PX4's accelerometer at rest: specific force up, FRD z down
  m.xgyro = 0.1f;
  const ImuSample imu = imuFromHighresImu(m);
  expectNear(imu.accel, Vec3(0.0, 0.0, 9.81), 1e-5);
  expectNear(imu.gyro, Vec3(0.1, 0.0, 0.0), 1e-7);
  const mavlink::HighresImu back = highresImuFromImu(imu);
  EXPECT_FLOAT_EQ(back.zacc, -9.81f);
}

}  // namespace
}  // namespace sdlqr::px4
