#include "sdlqr/px4/estimate_messages.hpp"

#include <cmath>
#include <limits>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/px4/frames.hpp"

namespace sdlqr::px4 {

namespace {

// Indices of the variances on the diagonal of ODOMETRY's 6x6 upper-right triangle, row-major.
constexpr int kDiagonal[6] = {0, 6, 11, 15, 18, 20};

template <class T>
Vec3 vec(T x, T y, T z) {
  return Vec3(static_cast<double>(x), static_cast<double>(y), static_cast<double>(z));
}

// 1-sigma of a variance; 0 (unknown) for NaN or a negative value.
double sigma(float variance) { return variance >= 0.0f ? std::sqrt(static_cast<double>(variance)) : 0.0; }

uint32_t bootMilliseconds(int64_t utime) { return static_cast<uint32_t>(std::max<int64_t>(0, utime) / 1000); }

// A vector into three float fields of a message.
void put(const Vec3& v, float& x, float& y, float& z) {
  x = static_cast<float>(v[0]);
  y = static_cast<float>(v[1]);
  z = static_cast<float>(v[2]);
}

}  // namespace

StateEstimate estimateFromOdometry(const mavlink::Odometry& m, RejectReason* reason) {
  *reason = RejectReason::kNone;
  StateEstimate e;
  const bool velocity_local = m.child_frame_id == mavlink::mav_frame::kLocalNed;
  const bool velocity_body = m.child_frame_id == mavlink::mav_frame::kBodyFrd;
  if (m.frame_id != mavlink::mav_frame::kLocalNed || !(velocity_local || velocity_body)) {
    *reason = RejectReason::kBadEnum;
    return e;
  }
  e.utime = static_cast<int64_t>(std::min<uint64_t>(m.time_usec, std::numeric_limits<int64_t>::max()));
  e.position = nedToWorld(vec(m.x, m.y, m.z));
  e.orientation = nedFrdToWorldBody(Quat(m.q[0], m.q[1], m.q[2], m.q[3]));
  const Vec3 velocity = vec(m.vx, m.vy, m.vz);
  e.velocity = velocity_local ? nedToWorld(velocity) : quat::rotate(e.orientation, frdToBody(velocity));
  e.body_rate = frdToBody(vec(m.rollspeed, m.pitchspeed, m.yawspeed));
  const Vec3 position_sigma(sigma(m.pose_covariance[kDiagonal[0]]), sigma(m.pose_covariance[kDiagonal[1]]),
                            sigma(m.pose_covariance[kDiagonal[2]]));
  e.position_std = Vec3(position_sigma[1], position_sigma[0], position_sigma[2]);  // NED axes -> world axes
  e.attitude_std = Vec3(sigma(m.pose_covariance[kDiagonal[3]]), sigma(m.pose_covariance[kDiagonal[4]]),
                        sigma(m.pose_covariance[kDiagonal[5]]));
  e.status = EstimatorStatus::kOk;
  return e;
}

StateEstimate estimateFromPositionAndAttitude(const mavlink::LocalPositionNed& position,
                                              const mavlink::AttitudeQuaternion& attitude) {
  StateEstimate e;
  e.utime = static_cast<int64_t>(position.time_boot_ms) * 1000;
  e.position = nedToWorld(vec(position.x, position.y, position.z));
  e.velocity = nedToWorld(vec(position.vx, position.vy, position.vz));
  e.orientation = nedFrdToWorldBody(Quat(attitude.q1, attitude.q2, attitude.q3, attitude.q4));
  e.body_rate = frdToBody(vec(attitude.rollspeed, attitude.pitchspeed, attitude.yawspeed));
  e.status = EstimatorStatus::kOk;
  return e;
}

ImuSample imuFromHighresImu(const mavlink::HighresImu& m) {
  ImuSample imu;
  imu.utime = static_cast<int64_t>(std::min<uint64_t>(m.time_usec, std::numeric_limits<int64_t>::max()));
  imu.gyro = frdToBody(vec(m.xgyro, m.ygyro, m.zgyro));
  imu.accel = frdToBody(vec(m.xacc, m.yacc, m.zacc));
  return imu;
}

mavlink::Odometry odometryFromEstimate(const StateEstimate& e) {
  mavlink::Odometry m;
  m.time_usec = static_cast<uint64_t>(std::max<int64_t>(0, e.utime));
  m.frame_id = mavlink::mav_frame::kLocalNed;
  m.child_frame_id = mavlink::mav_frame::kLocalNed;
  const Quat q = worldBodyToNedFrd(e.orientation);
  put(worldToNed(e.position), m.x, m.y, m.z);
  for (int i = 0; i < 4; ++i) m.q[i] = static_cast<float>(q[i]);
  put(worldToNed(e.velocity), m.vx, m.vy, m.vz);
  put(bodyToFrd(e.body_rate), m.rollspeed, m.pitchspeed, m.yawspeed);
  m.pose_covariance.fill(std::numeric_limits<float>::quiet_NaN());
  m.velocity_covariance.fill(std::numeric_limits<float>::quiet_NaN());
  const Vec3 ned_sigma = worldToNed(e.position_std).cwiseAbs();
  for (int i = 0; i < 3; ++i) {
    m.pose_covariance[kDiagonal[i]] = static_cast<float>(ned_sigma[i] * ned_sigma[i]);
    m.pose_covariance[kDiagonal[3 + i]] = static_cast<float>(e.attitude_std[i] * e.attitude_std[i]);
  }
  m.estimator_type = mavlink::mav_estimator_type::kAutopilot;
  return m;
}

mavlink::HighresImu highresImuFromImu(const ImuSample& imu) {
  mavlink::HighresImu m;
  m.time_usec = static_cast<uint64_t>(std::max<int64_t>(0, imu.utime));
  put(bodyToFrd(imu.accel), m.xacc, m.yacc, m.zacc);
  put(bodyToFrd(imu.gyro), m.xgyro, m.ygyro, m.zgyro);
  m.fields_updated = 0x3F;  // accelerometer and gyro, the fields this emulator fills
  return m;
}

mavlink::LocalPositionNed localPositionFromEstimate(const StateEstimate& e) {
  mavlink::LocalPositionNed m;
  m.time_boot_ms = bootMilliseconds(e.utime);
  put(worldToNed(e.position), m.x, m.y, m.z);
  put(worldToNed(e.velocity), m.vx, m.vy, m.vz);
  return m;
}

mavlink::AttitudeQuaternion attitudeFromEstimate(const StateEstimate& e) {
  mavlink::AttitudeQuaternion m;
  m.time_boot_ms = bootMilliseconds(e.utime);
  const Quat q = worldBodyToNedFrd(e.orientation);
  m.q1 = static_cast<float>(q[0]);
  m.q2 = static_cast<float>(q[1]);
  m.q3 = static_cast<float>(q[2]);
  m.q4 = static_cast<float>(q[3]);
  put(bodyToFrd(e.body_rate), m.rollspeed, m.pitchspeed, m.yawspeed);
  return m;
}

}  // namespace sdlqr::px4
