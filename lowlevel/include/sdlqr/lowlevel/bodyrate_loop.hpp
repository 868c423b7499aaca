#pragma once
// The bodyrate loop: one step per IMU sample. Ties together input checks, arming, the rate PID,
// the mixer, the IMU-only attitude filter, ground detection and the failsafe.
//
// Modes (MotorCommand::mode):
//   DISARMED --ARM/TAKEOFF--> IDLE (armed, rotors at idle) --fresh RATE_CMD--> RATE
//   RATE --no valid RATE_CMD for rate_cmd_timeout of IMU time--> FAILSAFE --fresh RATE_CMD--> RATE
//   RATE --at rest, thrust below hover and the IMU reading more than it gives, for landed_time,
//          or so when RATE_CMD stops--> DISARMED
//   FAILSAFE --touchdown--> DISARMED;   DISARM (or LAND while IDLE) --> DISARMED from anywhere
// Pure: time comes only from the IMU samples; step() does not allocate.

#include <array>
#include <cstdint>

#include "sdlqr/health/validate.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/model.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/lowlevel/attitude_filter.hpp"
#include "sdlqr/lowlevel/failsafe.hpp"
#include "sdlqr/lowlevel/ground_detector.hpp"
#include "sdlqr/lowlevel/input_checks.hpp"
#include "sdlqr/lowlevel/lowlevel_params.hpp"
#include "sdlqr/lowlevel/mixer.hpp"
#include "sdlqr/lowlevel/rate_control.hpp"

namespace sdlqr::lowlevel {

struct LowlevelCounters {
  int64_t imu_accepted = 0;
  std::array<int64_t, kRejectReasonCount> imu_rejected{};  // indexed by RejectReason
  int64_t imu_resyncs = 0;          // clock restarts accepted after a run of time rejects
  int64_t rate_cmd_accepted = 0;
  std::array<int64_t, kRejectReasonCount> rate_cmd_rejected{};  // indexed by RejectReason
  int64_t mass_rejected = 0;
  int64_t arm_refused = 0;
  int64_t failsafe_entries = 0;
  int64_t failsafe_recoveries = 0;  // fresh RATE_CMD took over again
  int64_t failsafe_touchdowns = 0;  // disarmed on the ground by the failsafe
  int64_t auto_disarms = 0;         // landed in RATE mode
  int64_t saturated_steps = 0;      // mixer could not deliver the demand
  int64_t nonfinite_outputs = 0;    // caught before reaching the motors (should stay 0)
};

struct LowlevelStatus {
  MotorMode mode = MotorMode::kDisarmed;
  int64_t imu_utime = kNoTime;
  Vec3 rate_setpoint = Vec3::Zero();  // [rad/s]
  double thrust_setpoint = 0.0;       // [m/s^2]
  Vec3 rate = Vec3::Zero();           // [rad/s] bias-corrected gyro
  Vec3 torque_demand = Vec3::Zero();  // [N m]
  MixerResult mix;
  RateController::Status pid;
  Quat attitude = identityQuat();     // IMU-only estimate
  double vertical_velocity = 0.0;     // [m/s] IMU-only estimate
  double hover_thrust = 0.0;          // [m/s^2] learned
  double command_age = 0.0;           // [s] IMU time minus utime of the last valid RATE_CMD
  bool maybe_landed = false;
  double landed_time = 0.0;           // [s] towards auto-disarm
};

class BodyrateLoop {
 public:
  // Throws std::invalid_argument on invalid parameters. `limits` gives the stack's body-rate bound
  // (RATE_CMD |omega|, and the failsafe's levelling rate must stay within it).
  BodyrateLoop(const VehicleParams& vehicle, const LowlevelParams& params, const ValidationLimits& limits,
               double gravity = kDefaultGravity);

  // Validates and keeps the command (latest wins). Returns why it was refused, kNone if kept.
  RejectReason setRateCommand(const RateCommand& command);
  // ARM, DISARM, TAKEOFF (arms), LAND (disarms when idle on the ground); GOTO is for the
  // controller. Returns false when refused (arming before the first IMU sample).
  bool handleCommand(const Command& command);
  // Run-time mass [kg] (PARAMS FIELD_MASS). Refused unless VehicleParams::massInvalidReason accepts it.
  bool setMass(double mass);

  // One loop iteration. A rejected sample (see lastImuReject()) leaves the loop untouched and
  // returns the previous command unchanged.
  MotorCommand step(const ImuSample& sample);

  RejectReason lastImuReject() const { return last_imu_reject_; }
  MotorMode mode() const { return status_.mode; }
  const LowlevelStatus& status() const { return status_; }
  const LowlevelCounters& counters() const { return counters_; }
  double mass() const { return mass_; }
  const LowlevelParams& params() const { return params_; }

 private:
  void enter(MotorMode mode);
  void updateModes();
  void flyRate(const Vec3& rate, double dt);
  void flyFailsafe(const Vec3& rate, double dt);
  void track(const Vec3& rate, const Vec3& rate_sp, double thrust, bool landed, double dt);
  double maxCommandThrust() const { return 4.0 * vehicle_.max_rotor_thrust / mass_; }

  VehicleParams vehicle_;
  LowlevelParams params_;
  double gravity_;
  double max_body_rate_;  // [rad/s]
  double mass_;
  Mat3 inertia_;

  RateController rate_controller_;
  Mixer mixer_;
  AttitudeFilter attitude_filter_;
  GroundDetector ground_detector_;
  Failsafe failsafe_;

  RateCommand command_;
  int64_t command_utime_ = kNoTime;
  bool command_pending_ = false;  // accepted since the last mode change that needs a fresh one
  int64_t last_imu_utime_ = kNoTime;
  int consecutive_time_rejects_ = 0;
  RejectReason last_imu_reject_ = RejectReason::kNone;
  double rotor_specific_force_ = 0.0;  // [m/s^2] rotor thrust after the motor lag, over the mass
  Vec4 thrust_ = Vec4::Zero();
  MotorCommand output_;
  int64_t output_seq_ = 0;
  LowlevelStatus status_;
  LowlevelCounters counters_;
};

}  // namespace sdlqr::lowlevel
