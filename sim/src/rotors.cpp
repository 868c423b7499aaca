#include "sdlqr/sim/rotors.hpp"

#include <algorithm>
#include <cmath>

namespace sdlqr::sim {

Vec4 saturatedSetpoint(const MotorCommand& command, const VehicleParams& vehicle) {
  if (!command.armed) return Vec4::Zero();
  Vec4 setpoint;
  for (int i = 0; i < 4; ++i) {
    setpoint[i] = std::clamp(command.thrust[i], vehicle.min_rotor_thrust, vehicle.max_rotor_thrust);
  }
  return setpoint;
}

MotorLag::MotorLag(double time_constant, double step)
    : time_constant_(time_constant), half_step_(0.5 * step), step_(step) {
  remaining_half_step_ = remaining(half_step_);
  remaining_step_ = remaining(step_);
}

double MotorLag::remaining(double tau) const {
  return time_constant_ > 0.0 ? std::exp(-tau / time_constant_) : 0.0;
}

Vec4 MotorLag::thrustAt(double tau) const {
  if (tau <= 0.0) return thrust_;
  const double factor = tau == half_step_ ? remaining_half_step_ : tau == step_ ? remaining_step_ : remaining(tau);
  return setpoint_ + factor * (thrust_ - setpoint_);
}

RotorWrench::RotorWrench(const VehicleParams& vehicle, double gravity)
    : effectiveness_(vehicle.effectiveness()),
      rotor_drag_(vehicle.rotor_drag),
      mass_(vehicle.mass),
      hover_thrust_per_rotor_(vehicle.hoverThrustPerRotor(gravity)) {}

RotorWrench::Load RotorWrench::load(const Vec4& thrust) const {
  Load load;
  load.thrust_and_torques = effectiveness_ * thrust;
  Vec4 spinning;
  for (int i = 0; i < 4; ++i) spinning[i] = std::max(thrust[i], 0.0);
  // Divisions and square roots as vector operations (the same values), summed in rotor order.
  const Vec4 speed_ratios = (spinning / hover_thrust_per_rotor_).cwiseSqrt();
  load.rotor_speed_ratio = 0.0;
  for (int i = 0; i < 4; ++i) load.rotor_speed_ratio += speed_ratios[i];
  load.rotor_speed_ratio *= 0.25;
  return load;
}

Wrench RotorWrench::operator()(const Load& load, const BodyState& s) const {
  const Mat3 body_to_world = quat::rotationMatrix(s.orientation.normalized());
  const Vec3 velocity_body = body_to_world.transpose() * s.velocity;
  const Vec3 drag_body = -mass_ * load.rotor_speed_ratio * rotor_drag_.cwiseProduct(velocity_body);

  Wrench w;
  w.force_world = body_to_world * (Vec3(0.0, 0.0, load.thrust_and_torques[0]) + drag_body);
  w.torque_body = load.thrust_and_torques.tail<3>();
  return w;
}

}  // namespace sdlqr::sim
