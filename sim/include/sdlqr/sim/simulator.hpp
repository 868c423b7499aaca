#pragma once
// The plant: rigid body + rotors + battery + ground + disturbances + sensors, advanced one RK4
// physics step per call. It owns the simulation clock (utime = steps x period) and tells the
// caller which sensor messages are due at each step. Pure: no clock, no I/O, no allocation in
// step(); the same seed and the same inputs give the same flight bit for bit.

#include <cstdint>
#include <optional>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/sim/battery.hpp"
#include "sdlqr/sim/disturbances.hpp"
#include "sdlqr/sim/imu_model.hpp"
#include "sdlqr/sim/input_checks.hpp"
#include "sdlqr/sim/rigid_body.hpp"
#include "sdlqr/sim/rotors.hpp"
#include "sdlqr/sim/sim_params.hpp"
#include "sdlqr/sim/stress_params.hpp"
#include "sdlqr/sim/throw_hand.hpp"
#include "sdlqr/sim/vio_model.hpp"
#include "sdlqr/sim/wind.hpp"

namespace sdlqr::sim {

// What to publish after a step; each stream has its own seq.
struct StepOutput {
  std::optional<ImuSample> imu;
  std::optional<VioPose> vio;     // captured earlier; published now
  std::optional<SimTruth> truth;
};

class Simulator {
 public:
  // Throws std::invalid_argument when the parameters are invalid or inconsistent. `stress` is the
  // scenario's world (plant mismatch, wind, airborne start, throw); its defaults change nothing.
  Simulator(const VehicleParams& vehicle, const SimParams& params);  // seed from params.seed
  Simulator(const VehicleParams& vehicle, const SimParams& params, uint64_t seed, const SimStress& stress = {});

  // Latest command wins, from the next step on. A command failing checkMotorCommand is ignored.
  RejectReason setMotorCommand(const MotorCommand& command);
  // Schedules an external wrench (start_utime in the past or 0: from the next step).
  RejectReason addDisturbance(const Disturbance& disturbance);

  // Advances exactly one physics period.
  StepOutput step();

  int64_t utime() const { return step_ * period_us_; }
  int64_t stepCount() const { return step_; }
  double period() const { return dt_; }
  SimTruth truth() const;

  const BodyState& body() const { return body_; }
  bool onGround() const { return on_ground_; }
  bool crashed() const { return crashed_; }
  // Per-rotor thrust [N] produced now: motor lag output times the battery's thrust scale and the
  // plant's thrust coefficient.
  Vec4 rotorThrust() const { return thrustScale() * motors_.thrust(); }
  // [m/s] world, the air's velocity at the vehicle during the last step.
  const Vec3& windVelocity() const { return wind_velocity_; }
  // The true airframe (the vehicle file with the scenario's plant override).
  const VehicleParams& plant() const { return plant_; }
  const Vec3& acceleration() const { return acceleration_; }
  const Battery& battery() const { return battery_; }
  const ImuModel& imu() const { return imu_; }

  // Places the vehicle (tests, scenario set-up): a state at z <= 0 rests on the ground.
  // motor_thrust sets the motor-lag state, e.g. hover thrust for a vehicle dropped in hovering.
  void setBodyState(const BodyState& state, const Vec4& motor_thrust = Vec4::Zero());

 private:
  double thrustScale() const { return battery_.thrustScale() * stress_.plant.thrust_scale; }
  Wrench wrenchOf(const RotorWrench::Load& rotors, const BodyState& s, int64_t start_utime) const;

  VehicleParams vehicle_;  // what the stack assumes: MOTOR_CMD checks, the battery's calibration
  SimParams params_;
  SimStress stress_;
  VehicleParams plant_;    // what flies
  BodyProperties body_properties_;
  RotorWrench rotor_wrench_;
  MotorLag motors_;
  Battery battery_;
  DisturbanceSet disturbances_;
  ImuModel imu_;
  VioModel vio_;
  Wind wind_;
  ThrowHand hand_;
  double dt_;
  int64_t period_us_;
  int imu_decimation_;
  int truth_decimation_;

  int64_t step_ = 0;
  BodyState body_;
  Vec3 acceleration_ = Vec3::Zero();
  Vec3 external_force_ = Vec3::Zero();
  Vec3 wind_velocity_ = Vec3::Zero();
  bool on_ground_ = true;
  bool crashed_ = false;
  bool payload_dropped_ = false;  // stress_.payload_drop has happened: body_properties_.mass is the lighter one
  int64_t truth_seq_ = 0;
};

}  // namespace sdlqr::sim
