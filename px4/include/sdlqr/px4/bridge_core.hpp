#pragma once
// sdlqr-px4's core: the stack as a PX4 companion computer, bus-free and clock-free. One method per
// input, as every process core (docs/architecture.md §5); the main binds the bus and the MAVLink link.
//
//   from PX4 (onBytes)  HEARTBEAT: link, armed, flight mode. ODOMETRY (or LOCAL_POSITION_NED with
//                       ATTITUDE_QUATERNION where ODOMETRY is not streamed): STATE_EST, and the
//                       vehicle's clock as SIM_CLOCK (the scenario player's clock); HIGHRES_IMU:
//                       IMU (for the log); EXTENDED_SYS_STATE: landed state; COMMAND_ACK: the command
//                       in flight (command_sender.hpp). Bad input counted and dropped (parser.hpp,
//                       then the stack's validate()), never on the bus.
//   RATE_CMD            -> SET_ATTITUDE_TARGET: body rates FRD and PX4's normalized thrust
//                       (thrust_map.hpp), attitude ignored (type_mask 128), every controller tick
//   COMMAND             ARM, TAKEOFF, GOTO: fly (offboard handshake, arm); LAND: once PX4 reports the
//                       vehicle on the ground, disarm; DISARM: disarm
//   onWallTime          our HEARTBEAT (MAV_TYPE_ONBOARD_CONTROLLER) at 1 Hz; stream requests
//                       (MAV_CMD_SET_MESSAGE_INTERVAL); the offboard handshake; command retries;
//                       zero-thrust setpoints while PX4 reports the vehicle on the ground and no
//                       RATE_CMD comes; the link watchdog
//
// The handshake as PX4 requires it: setpoints streamed at >= offboard_stream_rate_hz for
// offboard_stream_s, then MAV_CMD_DO_SET_MODE OFFBOARD, then MAV_CMD_COMPONENT_ARM_DISARM, each
// resent until its COMMAND_ACK; a refusal is asked again after handshake_retry_s.
// Failsafes: no HEARTBEAT for heartbeat_timeout_s or no ODOMETRY for odometry_timeout_s is the stack's failsafe (counted; no
// STATE_EST, no setpoints; the controller stops on its own STATE_EST watchdog). A silent controller
// while airborne: nothing is streamed, so PX4's offboard-loss failsafe (COM_OF_LOSS_T,
// COM_OBL_RC_ACT) takes over. PX4 leaving OFFBOARD while our link held (a pilot, PX4's own
// failsafe) is final until the next ARM or TAKEOFF; after our own link loss it is asked again
// (reengage_after_link_loss). With `bench`, nothing is armed, no mode asked and no setpoint sent:
// the setpoints it would send are kept for display (sdlqr-px4 --bench).
// The stack's clock is PX4's (ODOMETRY time_usec, boot time: the emulated PX4's is the simulation
// time); with `clock_from_start` it counts from the whole second before the first estimate, so a
// scenario's times count from when the bridge connected, whatever PX4's uptime (a real vehicle).

#include <array>
#include <cstdint>
#include <optional>
#include <tuple>

#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"
#include "sdlqr/px4/bridge_params.hpp"
#include "sdlqr/px4/command_sender.hpp"
#include "sdlqr/px4/mavlink_endpoint.hpp"
#include "sdlqr/px4/px4_modes.hpp"
#include "sdlqr/px4/setpoint_stream.hpp"

namespace sdlqr::px4 {

// What the bridge knows of the autopilot.
struct AutopilotView {
  bool heard = false;           // a HEARTBEAT ever
  double heartbeat_s = -1e9;    // [s] wall time of the last one
  double odometry_s = -1e9;     // [s] of the last accepted estimate
  bool odometry_seen = false;
  bool armed = false;
  FlightMode mode;
  uint8_t landed_state = 0;     // MAV_LANDED_STATE
  int64_t vehicle_utime = -1;   // [us] the newest accepted estimate's time (PX4's clock)
};

enum class FlightIntent : uint8_t { kIdle, kFly, kLand, kDisarm };

struct BridgeOptions {
  bool bench = false;             // sdlqr-px4 --bench
  bool clock_from_start = false;  // sdlqr-px4 --clock start
};

// What the bridge is doing, for the HEARTBEAT and the bench display.
enum class BridgeState : uint8_t {
  kWaiting,      // no autopilot heard
  kStandby,      // connected, no flight asked
  kStreaming,    // flight asked: streaming until the stream qualifies
  kHandshake,    // OFFBOARD or ARM asked, waiting for PX4
  kFlying,       // PX4 armed in OFFBOARD
  kLanding,      // LAND: waiting for PX4's on-ground, then disarming
  kTakenOver,    // PX4 left OFFBOARD while our link held: final until the next ARM/TAKEOFF
  kLinkLost,     // the stack's failsafe
};
const char* stateName(BridgeState state);

class BridgeCore {
 public:
  // Throws std::invalid_argument on invalid parameters.
  BridgeCore(const BridgeParams& params, double gravity, const ValidationLimits& limits, MavlinkEndpoint& link,
             BridgeOptions options = {});

  // Bytes from the link (`datagram`: one whole UDP datagram); what they carry goes to `bus`.
  void onBytes(const uint8_t* data, size_t size, bool datagram, Outbox& bus);
  RejectReason onRateCommand(const RateCommand& command);
  RejectReason onCommand(const Command& command);
  void onWallTime(double now_s);

  // The bus side (sdlqr/messages/ports.hpp); the MAVLink side is onBytes and the link it was given.
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&BridgeCore::onRateCommand, 1},
        ports::Input{&BridgeCore::onCommand, 16},
    };
  }
  using Outputs = ports::Publishes<StateEstimate, SimClockTick, ImuSample>;

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const AutopilotView& autopilot() const { return view_; }
  BridgeState state() const { return state_; }
  FlightIntent intent() const { return intent_; }
  // The last setpoint sent (or, on the bench, that would have been sent) and estimate published.
  const mavlink::SetAttitudeTarget& lastSetpoint() const { return last_setpoint_; }
  const StateEstimate& lastEstimate() const { return last_estimate_; }
  int wallTimePeriodMs() const;

 private:
  template <class Message>
  void handle(const Message&) {}  // a message the bridge does not use
  void handle(const mavlink::Heartbeat& m);
  void handle(const mavlink::Odometry& m);
  void handle(const mavlink::LocalPositionNed& m);
  void handle(const mavlink::AttitudeQuaternion& m);
  void handle(const mavlink::HighresImu& m);
  void handle(const mavlink::ExtendedSysState& m);
  void handle(const mavlink::CommandAck& m);
  void publishEstimate(StateEstimate estimate, RejectReason reason, const char* source);
  int64_t stackTime(int64_t px4_utime);  // PX4's time -> the stack's

  void checkLink();
  void requestStreams();
  void sendHeartbeat();
  void streamIdle();
  void advanceHandshake();
  void onCommandResult(const CommandResult& result);
  void sendCommand(uint16_t command, float p1 = 0, float p2 = 0, float p3 = 0, float p4 = 0);
  void send(const mavlink::SetAttitudeTarget& setpoint);
  bool onGround() const;
  bool linkUp() const { return state_ != BridgeState::kLinkLost && view_.heard; }
  void updateState();
  void countMirror();

  BridgeParams params_;
  double gravity_;
  ValidationLimits limits_;
  MavlinkEndpoint& link_;
  bool bench_;
  bool clock_from_start_;
  int64_t clock_offset_us_ = -1;  // PX4's time of the stack's 0 (-1 before the first estimate)
  ProcessHealth health_;
  CommandSender commands_;
  SetpointStream stream_;
  AutopilotView view_;
  FlightIntent intent_ = FlightIntent::kIdle;
  BridgeState state_ = BridgeState::kWaiting;
  Outbox* bus_ = nullptr;  // during onBytes

  double now_s_ = 0.0;
  double next_heartbeat_s_ = 0.0;
  double last_rate_cmd_s_ = -1e9;
  double last_idle_s_ = -1e9;
  double retry_after_s_ = 0.0;
  bool streams_requested_ = false;
  bool position_fallback_ = false;
  bool taken_over_ = false;
  bool link_lost_in_offboard_ = false;
  bool controller_silent_ = false;
  int64_t last_command_seq_ = -1;
  TimeGate rate_time_{1'000'000};
  ClockGate estimate_clock_;  // a forged far-future estimate cannot move the clock
  OrderGate command_order_;
  int64_t estimate_seq_ = 0, imu_seq_ = 0, clock_seq_ = 0;
  int64_t next_clock_utime_ = 0;
  std::optional<mavlink::AttitudeQuaternion> last_attitude_;
  mavlink::SetAttitudeTarget last_setpoint_;
  StateEstimate last_estimate_;

  struct Ids {
    Counters::Id setpoints, idle_setpoints, estimates, offboard_asked, offboard_refused, arm_asked, arm_refused,
        disarm_asked, commands_timed_out, acks_unexpected, left_by_autopilot, left_in_link_loss, no_heartbeat,
        no_odometry, controller_silent, armed, mode, landed_state, link_sent, link_failures, frames,
        skipped_bytes, clock_offset;
    std::array<Counters::Id, mavlink::kFrameDropCount> drops;
  } ids_;
  std::array<Counters::Id, kRejectReasonCount> estimate_rejects_;  // registered on first use
};

}  // namespace sdlqr::px4
