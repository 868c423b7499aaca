#pragma once
// Everything sdlqr-px4 reads from the `px4:` section of the vehicle file (declared in
// bridge_params.cpp; PX4's own rules the defaults follow are cited there).

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/px4/command_sender.hpp"
#include "sdlqr/px4/thrust_map.hpp"

namespace sdlqr::px4 {

struct BridgeParams : DeclaredParams<BridgeParams> {
  int system_id;             // our MAVLink system id (a companion shares its autopilot's)
  int autopilot_system;      // the autopilot's system and component ids (targets of our commands)
  int autopilot_component;
  double heartbeat_timeout_s;  // no HEARTBEAT (PX4: 1 Hz) for this long: the link is lost
  double odometry_timeout_s;   // no ODOMETRY for this long, once it flowed: the link is lost
  double odometry_rate_hz;   // asked of PX4 with MAV_CMD_SET_MESSAGE_INTERVAL
  double imu_rate_hz;
  double sys_state_rate_hz;
  double offboard_stream_s;  // setpoints streamed this long before OFFBOARD is asked for
  double offboard_stream_rate_hz;  // ... at least this often (PX4: above 2 Hz)
  double idle_rate_hz;       // setpoints of zero thrust while on the ground with no RATE_CMD
  double rate_cmd_timeout_s;  // RATE_CMD silent this long while airborne: stop streaming
  double rate_cmd_max_age_s;  // RATE_CMD older than the newest estimate by this: not forwarded
  double handshake_retry_s;  // after OFFBOARD or ARM was refused, ask again after this
  bool reengage_after_link_loss;  // PX4 left OFFBOARD while our link was down: ask again once back
  ThrustMap thrust;
  CommandRetry commands;

  BridgeParams();
  static const ParamTable<BridgeParams>& declaration();
};

}  // namespace sdlqr::px4
