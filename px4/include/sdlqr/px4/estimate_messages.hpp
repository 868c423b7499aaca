#pragma once
// PX4's state messages <-> sdlqr's, through frames.hpp only. The bridge reads what PX4 streams
// (ODOMETRY, or LOCAL_POSITION_NED with ATTITUDE_QUATERNION where ODOMETRY is not streamed, and
// HIGHRES_IMU); the emulated PX4 writes them from its own estimator and IMU, as PX4 does:
//   ODOMETRY  frame_id LOCAL_NED, child_frame_id LOCAL_NED (PX4's EKF2 publishes velocity in the
//             local frame: PX4 streams/ODOMETRY.hpp), body rates FRD, estimator_type AUTOPILOT,
//             the pose and velocity variances on the covariance diagonal, the rest NaN
// A message from PX4 becomes a StateEstimate that the caller then validates with the stack's own
// validate() (NaN, |q| far from 1, out of range), so every check lives in one place. Frames other
// than LOCAL_NED (pose) and LOCAL_NED or BODY_FRD (velocity) are refused (kBadEnum). Pure.

#include <optional>

#include "sdlqr/health/reject_reason.hpp"
#include "sdlqr/mavlink/messages.hpp"
#include "sdlqr/messages/messages.hpp"

namespace sdlqr::px4 {

// ODOMETRY -> STATE_EST (utime = time_usec, status OK; seq left to the caller). kBadEnum in
// *reason for a frame it cannot convert.
StateEstimate estimateFromOdometry(const mavlink::Odometry& m, RejectReason* reason);
// LOCAL_POSITION_NED and the ATTITUDE_QUATERNION paired with it -> STATE_EST (utime from the
// position's time_boot_ms; no covariance: std 0).
StateEstimate estimateFromPositionAndAttitude(const mavlink::LocalPositionNed& position,
                                              const mavlink::AttitudeQuaternion& attitude);
// HIGHRES_IMU -> IMU (body frame, utime = time_usec).
ImuSample imuFromHighresImu(const mavlink::HighresImu& m);

// The emulated PX4's side.
mavlink::Odometry odometryFromEstimate(const StateEstimate& estimate);
mavlink::HighresImu highresImuFromImu(const ImuSample& imu);
mavlink::LocalPositionNed localPositionFromEstimate(const StateEstimate& estimate);
mavlink::AttitudeQuaternion attitudeFromEstimate(const StateEstimate& estimate);

}  // namespace sdlqr::px4
