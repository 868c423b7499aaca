#pragma once
// An autopilot to fly against here (no PX4 binary can be installed on these machines): the
// stack's own simulator, estimator and bodyrate loop — the very cores sdlqr-sim, sdlqr-estimator
// and sdlqr-lowlevel run — behind a MAVLink 2 endpoint that behaves as PX4 documents for offboard
// mode. Bus-free and clock-free: the main paces step() and binds the link and the bus.
//
//   step()            one physics step (simulation time is the emulated PX4's clock): IMU to the
//                     bodyrate loop and the estimator (PX4's EKF2 stand-in, fusing IMU and VIO),
//                     MOTOR_CMD back to the plant; what the flight mode flies; the commander's
//                     offboard-loss rule; the streams due (streams.hpp: PX4's onboard rates, or as
//                     MAV_CMD_SET_MESSAGE_INTERVAL set them). SIM_TRUTH and MOTOR_CMD go to the bus
//                     for the log (the world's truth, PX4's actuator outputs).
//   onBytes()         SET_ATTITUDE_TARGET: in OFFBOARD, body rates (FRD) and normalized thrust become
//                     the bodyrate loop's command (the airframe's thrust map), held until the next
//                     as PX4's rate controller holds vehicle_rates_setpoint; in any mode each one is
//                     the offboard signal (commander.hpp). COMMAND_LONG: DO_SET_MODE,
//                     COMPONENT_ARM_DISARM, SET_MESSAGE_INTERVAL answered with COMMAND_ACK; any other
//                     command UNSUPPORTED. Targets other than ours (or 0) are ignored, as PX4 does.
//   Hold and Land     a position loop stands in for PX4's (controller/geometric_control.hpp): Hold
//                     keeps the point where it began, Land sinks at MPC_LAND_SPEED; on the ground the
//                     bodyrate loop's land detector disarms (PX4's COM_DISARM_LAND). The landed state
//                     (EXTENDED_SYS_STATE, disarm checks) is land_detector.hpp's.
// What it does not emulate is listed in docs/px4.md.

#include <optional>
#include <tuple>

#include "sdlqr/estimator/estimator_core.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/lowlevel/lowlevel_core.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"
#include "sdlqr/px4/mavlink_endpoint.hpp"
#include "sdlqr/px4/thrust_map.hpp"
#include "sdlqr/px4emu/commander.hpp"
#include "sdlqr/px4emu/emulator_params.hpp"
#include "sdlqr/px4emu/land_detector.hpp"
#include "sdlqr/px4emu/streams.hpp"
#include "sdlqr/sim/sim_core.hpp"

namespace sdlqr::px4emu {

// The vehicle-file sections the emulator reads.
struct EmulatorConfig {
  VehicleParams vehicle;
  sim::SimParams sim;
  estimator::EstimatorParams estimator;
  lowlevel::LowlevelParams lowlevel;
  LqrParams lqr;
  FaultParams faults;
  ValidationLimits validation;
  EmulatorParams emulator;
};

class EmulatorCore;
// What the emulator itself takes of the messages inside the vehicle (InProcessWiring's observer,
// shown each one before the inner cores): the newest IMU sample and estimate for its streams, the
// truth and the motor commands for the bus.
struct InnerObserver {
  EmulatorCore* core;
  template <class Message>
  void operator()(const Message& m) const;
};

class EmulatorCore {
 public:
  // Throws std::invalid_argument on invalid parameters.
  EmulatorCore(const EmulatorConfig& config, const sim::SimStress& stress, px4::MavlinkEndpoint& link);

  // One physics step. Returns true on the step the vehicle crashed (reported once).
  bool step(Outbox& bus);
  void onBytes(const uint8_t* data, size_t size, bool datagram);
  RejectReason onDisturbance(const Disturbance& disturbance);

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const Commander& commander() const { return commander_; }
  const sim::SimCore& sim() const { return sim_; }
  const lowlevel::LowlevelCore& lowlevel() const { return lowlevel_; }
  const Streams& streams() const { return streams_; }
  int64_t utime() const { return sim_.simulator().utime(); }
  uint8_t landedState() const;
  double hoverThrottle() const { return airframe_.hover_throttle; }

  // The bus side (sdlqr/messages/ports.hpp); the MAVLink side is onBytes and the link it was given.
  // SIM_CLOCK stays inside: the companion's bridge owns the scenario's clock (from ODOMETRY).
  static constexpr auto inputs() { return std::tuple{ports::Input{&EmulatorCore::onDisturbance, 16}}; }
  using Outputs = ports::Publishes<SimTruth, MotorCommand>;

  // The inner observer (InnerObserver): not for callers.
  void observe(const ImuSample& m) { imu_ = m; }
  void observe(const StateEstimate& m) { estimate_ = m; }
  void observe(const SimTruth& m) { bus_->publish(m); }
  void observe(const MotorCommand& m) { bus_->publish(m); }
  template <class Message>
  void observe(const Message&) {}

 private:
  template <class Message>
  void handle(const Message&, const mavlink::Frame&) {}
  void handle(const mavlink::SetAttitudeTarget& m, const mavlink::Frame& frame);
  void handle(const mavlink::CommandLong& m, const mavlink::Frame& frame);
  void handle(const mavlink::Heartbeat& m, const mavlink::Frame& frame);
  uint8_t execute(const mavlink::CommandLong& m);
  void fly();
  void flyNavigation(const StateEstimate& estimate);
  void commandLowlevel(const Vec3& body_rate, double thrust);
  void tellLowlevel(CommandType type);
  void sendStreams();
  template <class Make>
  bool streamIfDue(uint32_t message_id, int64_t now, Make make) {
    if (!streams_.due(message_id, now)) return false;
    link_.send(make());
    streams_.sent(message_id, now);
    return true;
  }
  void mirrorCounts();
  bool onGround() const { return land_detector_.landed(); }
  bool targetsUs(uint8_t system, uint8_t component) const;

  EmulatorConfig config_;
  px4::MavlinkEndpoint& link_;
  px4::ThrustMap airframe_;  // PX4's normalized thrust -> the bodyrate loop's c [m/s^2]
  sim::SimCore sim_;
  estimator::EstimatorCore estimator_;
  lowlevel::LowlevelCore lowlevel_;
  // Inside the vehicle, each message reaches the cores whose ports take it, as on the bus: the
  // bodyrate loop acts on an IMU sample before the estimator, the plant takes the motor commands.
  InnerObserver observer_{this};
  InProcessWiring<InnerObserver, lowlevel::LowlevelCore, estimator::EstimatorCore, sim::SimCore> inner_;
  Commander commander_;
  Streams streams_;
  LandDetector land_detector_;
  ProcessHealth health_;
  Outbox* bus_ = nullptr;  // during step()

  std::optional<StateEstimate> estimate_;  // the newest of the estimator
  int64_t odometry_sent_utime_ = -1;
  ImuSample imu_;                          // the newest sample
  std::optional<mavlink::SetAttitudeTarget> setpoint_;  // the newest accepted, held in OFFBOARD
  px4::FlightMode flown_mode_;             // the mode fly() last flew
  Vec3 hold_point_ = Vec3::Zero();
  double hold_yaw_ = 0.0;
  int64_t command_seq_ = 0, rate_seq_ = 0;
  bool crash_reported_ = false;
  int64_t last_flown_utime_ = -1;

  struct Ids {
    Counters::Id offboard_entered, offboard_refused, offboard_lost, arms, arms_refused, disarms, disarms_refused,
        setpoints, setpoints_ignored, commands_unsupported, armed, mode, crashes, frames, sent, send_failures,
        bad_crc, unsigned_frames, bad_signature, replayed, unknown_id, truncated;
  } ids_;
};

template <class Message>
void InnerObserver::operator()(const Message& m) const {
  core->observe(m);
}

}  // namespace sdlqr::px4emu
