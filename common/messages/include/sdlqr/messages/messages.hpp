#pragma once
// Plain message structs: what the libraries exchange. They mirror lcmtypes/*.lcm field for field
// (units and frames are documented there); common/bus converts between the two, so generated
// LCM types never reach algorithm code and the in-process closed loop needs no bus.

#include <cstdint>
#include <string>
#include <vector>

#include "sdlqr/math/types.hpp"

namespace sdlqr {

struct ImuSample {
  int64_t utime = 0;
  int64_t seq = 0;
  Vec3 gyro = Vec3::Zero();   // [rad/s] body
  Vec3 accel = Vec3::Zero();  // [m/s^2] specific force, body
};

struct VioPose {
  int64_t utime = 0;  // capture time
  int64_t seq = 0;
  int64_t publish_utime = 0;
  Vec3 position = Vec3::Zero();
  Quat orientation = identityQuat();
  double position_std = 0.0;
  double attitude_std = 0.0;
};

enum class EstimatorStatus : int8_t { kInitializing = 0, kOk = 1, kVioTimeout = 2 };

struct StateEstimate {
  int64_t utime = 0;
  int64_t seq = 0;
  Vec3 position = Vec3::Zero();
  Quat orientation = identityQuat();
  Vec3 velocity = Vec3::Zero();
  Vec3 body_rate = Vec3::Zero();
  Vec3 gyro_bias = Vec3::Zero();
  Vec3 accel_bias = Vec3::Zero();
  Vec3 position_std = Vec3::Zero();
  Vec3 attitude_std = Vec3::Zero();
  int64_t imu_seq = -1;
  int64_t vio_seq = -1;
  EstimatorStatus status = EstimatorStatus::kInitializing;

  State state() const { return makeState(position, orientation, velocity); }
};

enum class GainsFreshness : int8_t { kFresh = 0, kStale = 1, kFallback = 2 };

struct RateCommand {
  int64_t utime = 0;
  int64_t seq = 0;
  Vec3 body_rate = Vec3::Zero();
  double thrust = 0.0;  // [m/s^2] mass-normalized
  int64_t state_seq = -1;
  int64_t gains_seq = -1;
  int64_t reference_seq = -1;
  int8_t saturated = 0;  // bit 0 rate clipped, bit 1 thrust clipped
  GainsFreshness gains_status = GainsFreshness::kFresh;

  Input input() const { return makeInput(body_rate, thrust); }
};

enum class MotorMode : int8_t { kDisarmed = 0, kRate = 1, kFailsafe = 2, kIdle = 3 };

struct MotorCommand {
  int64_t utime = 0;
  int64_t seq = 0;
  Vec4 thrust = Vec4::Zero();  // [N] per rotor
  int64_t imu_seq = -1;
  bool armed = false;
  MotorMode mode = MotorMode::kDisarmed;
};

enum class GainsMethod : int8_t { kTangent = 0, kIterative = 1 };
enum class SolveStatus : int8_t { kOk = 0, kNotConverged = 1, kNumericalFailure = 2, kInvalidInput = 3 };

struct GainSet {
  int64_t utime = 0;
  int64_t seq = 0;
  GainMatrix K = GainMatrix::Zero();
  State x_lin = State::Zero();
  Input u_lin = Input::Zero();
  State q_diag = State::Zero();
  Input r_diag = Input::Zero();
  double dt = 0.0;
  double solve_us = 0.0;
  double residual = 0.0;
  int32_t iterations = 0;
  int64_t state_seq = -1;
  int64_t params_seq = -1;
  int64_t reference_seq = -1;  // REFERENCE whose input was linearized at (-1: hover input)
  GainsMethod method = GainsMethod::kTangent;
  SolveStatus status = SolveStatus::kOk;
};

enum class ReferenceMode : int8_t { kSetpoint = 0, kSpatial = 1, kTemporal = 2, kIdle = 3 };

struct Reference {
  int64_t utime = 0;
  int64_t seq = 0;
  State x = State::Zero();
  Input u = Input::Zero();
  int32_t index = 0;
  double gamma = 0.0;
  int64_t trajectory_seq = -1;
  int64_t state_seq = -1;
  int64_t command_seq = -1;  // last COMMAND handled
  int64_t params_seq = -1;   // last PARAMS handled (-1: configuration file)
  ReferenceMode mode = ReferenceMode::kIdle;
};

struct TrajectorySample {
  double t = 0.0;  // [s] from the start
  State x = State::Zero();
  Input u = Input::Zero();
};

struct Trajectory {
  int64_t utime = 0;
  int64_t seq = 0;
  int64_t start_utime = 0;
  ReferenceMode tracking = ReferenceMode::kSpatial;
  bool closed = false;
  std::vector<TrajectorySample> samples;
};

enum class DisturbanceMode : int8_t { kForce = 0, kHold = 1 };

struct Disturbance {
  int64_t utime = 0;
  int64_t seq = 0;
  int64_t start_utime = 0;
  double duration = 0.0;          // [s]
  Vec3 force = Vec3::Zero();      // [N] world
  Vec3 torque = Vec3::Zero();     // [N m] body
  Vec3 hold_position = Vec3::Zero();
  double hold_stiffness = 0.0;    // [N/m]
  double hold_damping = 0.0;      // [N s/m]
  DisturbanceMode mode = DisturbanceMode::kForce;
};

struct ParamsUpdate {
  static constexpr int32_t kWeights = 1;
  static constexpr int32_t kLimits = 2;
  static constexpr int32_t kMass = 4;
  static constexpr int32_t kTracking = 8;

  int64_t utime = 0;
  int64_t seq = 0;
  int32_t field_mask = 0;
  State q_diag = State::Zero();
  Input r_diag = Input::Zero();
  double omega_max = 0.0;
  double c_min = 0.0;
  double c_max = 0.0;
  double mass = 0.0;
  ReferenceMode tracking = ReferenceMode::kSpatial;
};

enum class CommandType : int8_t { kArm = 1, kDisarm = 2, kTakeoff = 3, kGoto = 4, kLand = 5 };

struct Command {
  int64_t utime = 0;
  int64_t seq = 0;
  CommandType command = CommandType::kArm;
  Vec3 position = Vec3::Zero();
  double yaw = 0.0;
};

struct SimTruth {
  int64_t utime = 0;
  int64_t seq = 0;
  Vec3 position = Vec3::Zero();
  Quat orientation = identityQuat();
  Vec3 velocity = Vec3::Zero();
  Vec3 body_rate = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec4 rotor_thrust = Vec4::Zero();
  Vec3 gyro_bias = Vec3::Zero();
  Vec3 accel_bias = Vec3::Zero();
  Vec3 external_force = Vec3::Zero();
  double battery_voltage = 0.0;
  double thrust_scale = 1.0;
  bool on_ground = true;
  bool crashed = false;
};

}  // namespace sdlqr
