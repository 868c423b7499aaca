#pragma once
// The lowlevel process, bus-free: the bodyrate loop's input checks and the gates of the rare
// inputs, the IMU and RATE_CMD watchdogs (wall time), the counters and the loop itself. One method
// per input message, each returning the rejection (kNone: accepted). sdlqr-lowlevel binds the
// bus to it; the in-process loop drives the same object.
//
//   IMU       the loop's checks, one step -> MOTOR_CMD through the Outbox
//   RATE_CMD  the loop's checks (range, order, lead over the IMU clock, age)
//   COMMAND, PARAMS  validate, OrderGate against the IMU clock (a replayed one is refused); a
//             re-sent COMMAND (the seq handled last) changes nothing; PARAMS mass the loop
//             cannot lift is kRefused
// No allocation on the IMU and RATE_CMD paths.

#include <array>

#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/health/watchdog_report.hpp"
#include "sdlqr/lowlevel/bodyrate_loop.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"

namespace sdlqr::lowlevel {

class LowlevelCore {
 public:
  // Throws std::invalid_argument on invalid parameters (as BodyrateLoop).
  LowlevelCore(const VehicleParams& vehicle, const LowlevelParams& params, double gravity, const FaultParams& faults,
               const ValidationLimits& limits = {});

  RejectReason onImu(const ImuSample& sample, Outbox& out);
  RejectReason onRateCommand(const RateCommand& command);
  RejectReason onCommand(const Command& command);
  RejectReason onParams(const ParamsUpdate& update);
  // Wall time [s]: without IMU samples nothing can be computed or sent (FAILSAFE); the RATE_CMD
  // age is judged by the loop in IMU time (its failsafe) and mirrored here on wall time.
  void onWallTime(double now_s);

  // Ports (sdlqr/messages/ports.hpp). A step longer than the IMU period is a missed deadline.
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&LowlevelCore::onImu, 64, std::chrono::microseconds(1000)},
        ports::Input{&LowlevelCore::onRateCommand, 1},
        ports::Input{&LowlevelCore::onCommand, 16},
        ports::Input{&LowlevelCore::onParams, 16},
    };
  }
  using Outputs = ports::Publishes<MotorCommand>;

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }
  const BodyrateLoop& loop() const { return loop_; }
  int wallTimePeriodMs() const;

 private:
  // Loop counters that are not message rejections, mirrored into the health by their increase.
  struct EventCounter {
    Counters::Id id;
    const int64_t* value;
    int64_t reported = 0;
  };
  void mirrorEvents();

  BodyrateLoop loop_;
  FaultParams faults_;
  ValidationLimits limits_;
  ProcessHealth health_;
  OrderGate command_order_, params_order_;
  StreamWatchdog imu_watchdog_, rate_watchdog_;
  double wall_now_s_ = 0.0;
  int64_t imu_utime_ = -1;
  int64_t last_command_seq_ = -1;
  std::array<EventCounter, 8> events_;
};

}  // namespace sdlqr::lowlevel
