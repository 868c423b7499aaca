#pragma once
// Messages with every field set (no zero that truncation could hide) for the frame and parser tests.

#include <vector>

#include "sdlqr/mavlink/messages.hpp"
#include "sdlqr/mavlink/parser.hpp"

namespace sdlqr::mavlink::test {

inline Odometry sampleOdometry() {
  Odometry m;
  m.time_usec = 123456789012ULL;
  m.frame_id = mav_frame::kLocalNed;
  m.child_frame_id = mav_frame::kLocalNed;
  m.x = 1.5f;
  m.y = -2.25f;
  m.z = -0.75f;
  m.q = {0.9f, 0.1f, -0.2f, 0.3f};
  m.vx = 0.5f;
  m.vy = -0.125f;
  m.vz = 0.25f;
  m.rollspeed = 0.01f;
  m.pitchspeed = -0.02f;
  m.yawspeed = 0.03f;
  for (size_t i = 0; i < 21; ++i) {
    m.pose_covariance[i] = 0.001f * static_cast<float>(i + 1);
    m.velocity_covariance[i] = -0.002f * static_cast<float>(i + 1);
  }
  m.reset_counter = 2;
  m.estimator_type = mav_estimator_type::kAutopilot;
  m.quality = 0;  // the last byte: cut by truncation
  return m;
}

inline SetAttitudeTarget sampleSetpoint() {
  SetAttitudeTarget m;
  m.time_boot_ms = 4242;
  m.target_system = 1;
  m.target_component = 1;
  m.type_mask = attitude_target_typemask::kAttitudeIgnore;
  m.q = {1.0f, 0.0f, 0.0f, 0.0f};
  m.body_roll_rate = 0.5f;
  m.body_pitch_rate = -0.25f;
  m.body_yaw_rate = 0.125f;
  m.thrust = 0.42f;
  return m;  // thrust_body zero: the frame's payload is cut to 39 bytes
}

// Every frame `parser` accepts from `bytes` (one datagram).
inline std::vector<Frame> parseAll(Parser& parser, const std::vector<uint8_t>& bytes, uint64_t now = 0) {
  std::vector<Frame> frames;
  parser.feed(bytes.data(), bytes.size(), now, [&](const Frame& f) { frames.push_back(f); });
  parser.endDatagram();
  return frames;
}

template <class Message>
std::vector<uint8_t> frameOf(FrameWriter& writer, const Message& m, uint64_t signing_time = 0) {
  std::vector<uint8_t> bytes(kMaxFrameSize);
  bytes.resize(writer.write(m, signing_time, bytes.data()));
  return bytes;
}

}  // namespace sdlqr::mavlink::test
