#include "sdlqr/px4/bench_display.hpp"

#include <cmath>
#include <cstdio>

#include "sdlqr/math/quaternion.hpp"
#include "sdlqr/px4/frames.hpp"

namespace sdlqr::px4 {

namespace {

// Roll, pitch, yaw [deg] of a rotation (Z-Y-X Tait-Bryan angles, as PX4's Eulerf).
Vec3 eulerDegrees(const Quat& q) {
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  const double roll = std::atan2(2.0 * (w * x + y * z), 1.0 - 2.0 * (x * x + y * y));
  const double pitch = std::asin(std::clamp(2.0 * (w * y - z * x), -1.0, 1.0));
  const double yaw = std::atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z));
  return Vec3(roll, pitch, yaw) * 180.0 / M_PI;
}

const char* landedName(uint8_t state) {
  switch (state) {
    case 1: return "on_ground";
    case 2: return "in_air";
    case 3: return "takeoff";
    case 4: return "landing";
    default: return "unknown";
  }
}

}  // namespace

std::string benchText(const BridgeCore& core) {
  const AutopilotView& v = core.autopilot();
  const StateEstimate& e = core.lastEstimate();
  const mavlink::SetAttitudeTarget& s = core.lastSetpoint();
  const Vec3 ned = worldToNed(e.position);
  const Vec3 px4_angles = eulerDegrees(worldBodyToNedFrd(e.orientation));
  const Vec3 sdlqr_angles = eulerDegrees(e.orientation);
  char text[1024];
  std::snprintf(text, sizeof text,
                "bench t=%.2f s  PX4 %s, %s, %s  bridge %s\n"
                "  PX4 (NED/FRD)  p [%7.3f %7.3f %7.3f] m  roll %6.1f pitch %6.1f yaw %6.1f deg\n"
                "  sdlqr (z up)   p [%7.3f %7.3f %7.3f] m  roll %6.1f pitch %6.1f yaw %6.1f deg  v [%6.2f %6.2f %6.2f] m/s\n"
                "  setpoint (FRD, not sent) rates [%6.2f %6.2f %6.2f] rad/s  thrust %.3f\n",
                1e-6 * static_cast<double>(e.utime), v.armed ? "ARMED" : "disarmed", modeName(v.mode),
                landedName(v.landed_state), stateName(core.state()), ned[0], ned[1], ned[2], px4_angles[0],
                px4_angles[1], px4_angles[2], e.position[0], e.position[1], e.position[2], sdlqr_angles[0],
                sdlqr_angles[1], sdlqr_angles[2], e.velocity[0], e.velocity[1], e.velocity[2],
                static_cast<double>(s.body_roll_rate), static_cast<double>(s.body_pitch_rate),
                static_cast<double>(s.body_yaw_rate), static_cast<double>(s.thrust));
  return text;
}

}  // namespace sdlqr::px4
