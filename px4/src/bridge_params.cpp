#include "sdlqr/px4/bridge_params.hpp"

namespace sdlqr::px4 {

BridgeParams::BridgeParams() { declaration().setDefaults(*this); }

const ParamTable<BridgeParams>& BridgeParams::declaration() {
  static const ParamTable<BridgeParams> table = [] {
    using P = BridgeParams;
    ParamTable<P> t("PX4 bridge (sdlqr-px4): MAVLink 2 to a PX4 autopilot in offboard mode (docs/px4.md)");
    t.integer("system_id", &P::system_id, 1, "-", Range::closed(1, 255), "our MAVLink system id (PX4's MAV_SYS_ID)");
    t.integer("autopilot_system", &P::autopilot_system, 1, "-", Range::closed(1, 255), "PX4's MAV_SYS_ID");
    t.integer("autopilot_component", &P::autopilot_component, 1, "-", Range::closed(1, 255),
              "PX4's component id (MAV_COMP_ID_AUTOPILOT1)");
    t.number("heartbeat_timeout_s", &P::heartbeat_timeout_s, 3.0, "s", Range::closed(1.5, 60.0),
             "without PX4's HEARTBEAT (1 Hz): link lost, the stack's failsafe (no STATE_EST, no setpoints)");
    t.number("odometry_timeout_s", &P::odometry_timeout_s, 0.5, "s", Range::closed(0.05, 10.0),
             "without ODOMETRY once it flowed: link lost, the stack's failsafe");
    t.number("odometry_rate_hz", &P::odometry_rate_hz, 250.0, "Hz", Range::closed(1.0, 1000.0),
             "ODOMETRY asked of PX4 (paper: a 250 Hz estimate)");
    t.number("imu_rate_hz", &P::imu_rate_hz, 50.0, "Hz", Range::closed(1.0, 1000.0), "HIGHRES_IMU asked of PX4");
    t.number("sys_state_rate_hz", &P::sys_state_rate_hz, 5.0, "Hz", Range::closed(1.0, 100.0),
             "EXTENDED_SYS_STATE (landed state) asked of PX4");
    t.number("offboard_stream_s", &P::offboard_stream_s, 1.0, "s", Range::closed(0.0, 10.0),
             "setpoints streamed before asking for OFFBOARD (PX4 docs: over a second)");
    t.number("offboard_stream_rate_hz", &P::offboard_stream_rate_hz, 2.0, "Hz", Range::closed(0.5, 100.0),
             "the stream's least rate (PX4 docs: above 2 Hz)");
    t.number("idle_rate_hz", &P::idle_rate_hz, 20.0, "Hz", Range::closed(2.0, 200.0),
             "zero-thrust setpoints while PX4 reports on ground and no RATE_CMD comes");
    t.number("rate_cmd_timeout_s", &P::rate_cmd_timeout_s, 0.1, "s", Range::closed(0.01, 5.0),
             "RATE_CMD silent this long while airborne: stop streaming (PX4's COM_OF_LOSS_T takes over)");
    t.number("rate_cmd_max_age_s", &P::rate_cmd_max_age_s, 0.05, "s", Range::closed(0.0, 1.0),
             "a RATE_CMD older than the newest estimate by more is stale, not forwarded");
    t.number("handshake_retry_s", &P::handshake_retry_s, 1.0, "s", Range::closed(0.1, 60.0),
             "after OFFBOARD or ARM was refused, ask again after this");
    t.flag("reengage_after_link_loss", &P::reengage_after_link_loss, true,
           "PX4 left OFFBOARD while our link was down: stream again and ask for OFFBOARD once it is back "
           "(never after a pilot's or PX4's own switch while the link held)");
    t.section("thrust", &P::thrust);
    t.section("commands", &P::commands);
    return t;
  }();
  return table;
}

}  // namespace sdlqr::px4
