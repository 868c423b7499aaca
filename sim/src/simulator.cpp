#include "sdlqr/sim/simulator.hpp"

#include <cmath>
#include <stdexcept>

#include "sdlqr/sim/ground.hpp"

namespace sdlqr::sim {

namespace {

// Runs before any member is built, so no model ever sees invalid parameters.
const VehicleParams& checked(const VehicleParams& vehicle, const SimParams& params) {
  if (const std::string why = vehicle.invalidReason(); !why.empty()) throw std::invalid_argument("vehicle." + why);
  if (const std::string why = params.invalidReason(); !why.empty()) throw std::invalid_argument("sim." + why);
  return vehicle;
}

// The vehicle file with the scenario's plant override: the airframe that really flies.
VehicleParams plantOf(const VehicleParams& vehicle, const PlantOverride& plant) {
  VehicleParams p = vehicle;
  p.mass *= plant.mass_scale;
  p.inertia_diag = p.inertia_diag.cwiseProduct(plant.inertia_scale);
  p.motor_time_constant *= plant.motor_time_constant_scale;
  return p;
}

const SimStress& checked(const SimStress& stress) {
  if (const std::string why = stress.invalidReason(); !why.empty()) throw std::invalid_argument("sim." + why);
  return stress;
}

Quat fromRollPitchYaw(const Vec3& degrees) {
  const Vec3 r = degrees * (M_PI / 180.0);
  const Quat roll = quat::exp(Vec3(r[0], 0.0, 0.0));
  const Quat pitch = quat::exp(Vec3(0.0, r[1], 0.0));
  return quat::multiply(quat::fromYaw(r[2]), quat::multiply(pitch, roll));
}

BodyState airborneState(const AirborneStart& start) {
  BodyState s;
  s.position = start.position;
  s.orientation = fromRollPitchYaw(start.attitude_deg);
  s.velocity = start.velocity;
  s.body_rate = start.body_rate;
  return s;
}

BodyProperties propertiesOf(const VehicleParams& vehicle, double gravity) {
  BodyProperties p;
  p.mass = vehicle.mass;
  p.inertia_diag = vehicle.inertia_diag;
  p.gravity = Vec3(0.0, 0.0, -gravity);
  return p;
}

}  // namespace

Simulator::Simulator(const VehicleParams& vehicle, const SimParams& params)
    : Simulator(vehicle, params, static_cast<uint64_t>(params.seed)) {}

Simulator::Simulator(const VehicleParams& vehicle, const SimParams& params, uint64_t seed, const SimStress& stress)
    : vehicle_(checked(vehicle, params)),
      params_(params),
      stress_(checked(stress)),
      plant_(plantOf(vehicle, stress.plant)),
      body_properties_(propertiesOf(plant_, params.gravity)),
      rotor_wrench_(plant_, params.gravity),
      motors_(plant_.motor_time_constant, params.physicsPeriod()),
      battery_(params.battery, vehicle, params.gravity),
      imu_(params.imu, seed),
      vio_(params.vio, params.physics_rate_hz, seed),
      wind_(stress.wind, params.physicsPeriod(), seed),
      hand_(stress.throw_event, params.initial_yaw),
      dt_(params.physicsPeriod()),
      period_us_(params.physicsPeriodUs()),
      imu_decimation_(params.physics_rate_hz / params.imu.rate_hz),
      truth_decimation_(params.physics_rate_hz / params.truth_rate_hz) {
  BodyState start;
  start.position = params.initial_position;
  start.orientation = quat::fromYaw(params.initial_yaw);
  setBodyState(start);
  if (stress_.airborne_start.enabled()) {
    const Vec4 hover = Vec4::Constant(vehicle_.hoverThrustPerRotor(params.gravity));
    setBodyState(airborneState(stress_.airborne_start), stress_.airborne_start.motors_spinning ? hover : Vec4::Zero());
  }
  if (stress_.throw_event.enabled()) setBodyState(hand_.stateAt(0.0));
}

void Simulator::setBodyState(const BodyState& state, const Vec4& motor_thrust) {
  on_ground_ = state.position.z() <= 0.0;
  body_ = on_ground_ ? restingOnGround(state) : state;
  body_.orientation.normalize();
  motors_.setThrust(motor_thrust);
  acceleration_.setZero();
}

RejectReason Simulator::setMotorCommand(const MotorCommand& command) {
  const RejectReason fault = checkMotorCommand(command, vehicle_);
  if (fault == RejectReason::kNone) motors_.setSetpoint(saturatedSetpoint(command, vehicle_));
  return fault;
}

RejectReason Simulator::addDisturbance(const Disturbance& disturbance) {
  const RejectReason fault = checkDisturbance(disturbance, params_.disturbance);
  if (fault != RejectReason::kNone) return fault;
  // The step that starts at utime() is the first that can feel it.
  return disturbances_.add(disturbance, utime()) ? RejectReason::kNone : RejectReason::kQueueFull;
}

// The schedule and the wind are sampled at the start of the step: their edges fall on step boundaries.
Wrench Simulator::wrenchOf(const RotorWrench::Load& rotors, const BodyState& s, int64_t start_utime) const {
  Wrench w;
  if (wind_.enabled() || stress_.plant.body_drag > 0.0) {
    // Drag acts on the velocity relative to the air.
    BodyState in_air = s;
    in_air.velocity -= wind_velocity_;
    w = rotor_wrench_(rotors, in_air);
    w.force_world += frameDrag(stress_.plant.body_drag, s.velocity, wind_velocity_);
  } else {
    w = rotor_wrench_(rotors, s);
  }
  const Wrench external = disturbances_.wrenchAt(start_utime, s);
  w.force_world += external.force_world;
  w.torque_body += external.torque_body;
  return w;
}

StepOutput Simulator::step() {
  const int64_t start_utime = utime();
  disturbances_.expire(start_utime);
  const PayloadDrop& drop = stress_.payload_drop;
  if (drop.enabled() && !payload_dropped_ && start_utime >= static_cast<int64_t>(drop.at * 1e6 + 0.5)) {
    body_properties_.mass = plant_.mass * drop.mass_scale;
    payload_dropped_ = true;
  }
  const double thrust_scale = thrustScale();
  wind_velocity_ = wind_.velocity();
  // The rotors at the step's start, middle (RK4's second and third stages) and end.
  const double half = 0.5 * dt_;
  const RotorWrench::Load start = rotor_wrench_.load(thrust_scale * motors_.thrustAt(0.0));
  const RotorWrench::Load middle = rotor_wrench_.load(thrust_scale * motors_.thrustAt(half));
  const RotorWrench::Load end = rotor_wrench_.load(thrust_scale * motors_.thrustAt(dt_));
  const auto wrench_at = [&](const BodyState& s, double tau) {
    if (tau <= 0.0) return wrenchOf(start, s, start_utime);
    if (tau == half) return wrenchOf(middle, s, start_utime);
    if (tau == dt_) return wrenchOf(end, s, start_utime);
    return wrenchOf(rotor_wrench_.load(thrust_scale * motors_.thrustAt(tau)), s, start_utime);
  };
  external_force_ = disturbances_.wrenchAt(start_utime, body_).force_world;

  const Vec3 velocity_before = body_.velocity;
  const double end_s = 1e-6 * static_cast<double>(start_utime + period_us_);
  if (hand_.holds(end_s)) {
    body_ = hand_.stateAt(end_s);  // the hand moves it, whatever the rotors do
    on_ground_ = false;
  } else {
    BodyState next = rk4Step(body_, dt_, body_properties_, wrench_at);
    const bool below_ground = next.position.z() < 0.0 || (on_ground_ && next.position.z() <= 0.0);
    if (below_ground) {
      if (!on_ground_ && isCrash(next, params_.ground)) crashed_ = true;
      next = restingOnGround(next);
    }
    on_ground_ = below_ground;
    body_ = next;
  }
  acceleration_ = (body_.velocity - velocity_before) / dt_;
  if (wind_.enabled()) wind_.advance();

  motors_.advance(dt_);
  battery_.update(dt_, rotorThrust());
  ++step_;

  StepOutput out;
  const int64_t now = utime();
  if (step_ % imu_decimation_ == 0) {
    const Vec3 specific_force =
        quat::rotateInverse(body_.orientation, acceleration_ - body_properties_.gravity);
    out.imu = imu_.sample(now, body_.body_rate, specific_force);
  }
  out.vio = vio_.step(step_, body_.position, body_.orientation);
  if (step_ % truth_decimation_ == 0) {
    out.truth = truth();
    out.truth->seq = truth_seq_++;
  }
  return out;
}

SimTruth Simulator::truth() const {
  SimTruth t;
  t.utime = utime();
  t.seq = truth_seq_;
  t.position = body_.position;
  t.orientation = body_.orientation;
  t.velocity = body_.velocity;
  t.body_rate = body_.body_rate;
  t.acceleration = acceleration_;
  t.rotor_thrust = rotorThrust();
  t.gyro_bias = imu_.gyroBias();
  t.accel_bias = imu_.accelBias();
  t.external_force = external_force_;
  t.battery_voltage = battery_.voltage();
  t.thrust_scale = battery_.thrustScale();
  t.on_ground = on_ground_;
  t.crashed = crashed_;
  return t;
}

}  // namespace sdlqr::sim
