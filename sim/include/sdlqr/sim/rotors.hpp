#pragma once
// The four rotors: per-rotor saturation of the setpoints, first-order motor lag, and the wrench
// the produced thrusts exert on the airframe (collective thrust, roll/pitch/yaw torques through
// VehicleParams::effectiveness(), and linear rotor drag).

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/sim/rigid_body.hpp"

namespace sdlqr::sim {

// Setpoints the ESCs would realize: disarmed means zero thrust, armed means clamped to
// [min_rotor_thrust, max_rotor_thrust] per rotor. Non-finite entries must be rejected earlier.
Vec4 saturatedSetpoint(const MotorCommand& command, const VehicleParams& vehicle);

// First-order lag from setpoint to thrust, solved exactly for a setpoint held over the step:
// T(tau) = T_sp + (T_0 - T_sp) exp(-tau / time_constant).
class MotorLag {
 public:
  // `step` [s]: the physics step, whose instants the integrator asks for at every step (step / 2,
  // step): their decay factors are computed once.
  MotorLag(double time_constant, double step);

  void setSetpoint(const Vec4& setpoint) { setpoint_ = setpoint; }
  const Vec4& setpoint() const { return setpoint_; }
  // Thrust tau seconds after the current step started.
  Vec4 thrustAt(double tau) const;
  // Moves the lag state dt seconds on.
  void advance(double dt) { thrust_ = thrustAt(dt); }
  const Vec4& thrust() const { return thrust_; }
  // Forces the lag state (a vehicle dropped into the air already hovering).
  void setThrust(const Vec4& thrust) { thrust_ = thrust; }

 private:
  // exp(-tau / time_constant), 0 without a lag.
  double remaining(double tau) const;

  double time_constant_;
  double half_step_, step_;
  double remaining_half_step_, remaining_step_;
  Vec4 setpoint_ = Vec4::Zero();
  Vec4 thrust_ = Vec4::Zero();
};

// The airframe's response to rotor thrusts, precomputed from VehicleParams.
class RotorWrench {
 public:
  RotorWrench(const VehicleParams& vehicle, double gravity);

  // What per-rotor thrusts [N] give whatever the body's state: collective thrust and torques, and
  // the mean rotor speed over hover rotor speed. The integrator's two mid-step stages share it.
  struct Load {
    Vec4 thrust_and_torques;
    double rotor_speed_ratio;
  };
  Load load(const Vec4& thrust) const;

  // Wrench of the given per-rotor thrusts [N] on a body in state s. Rotor drag is induced by the
  // spinning rotors: it grows with rotor speed (~ sqrt(thrust)) and equals the configured
  // mass-normalized coefficients at hover thrust, vanishing when the rotors stop.
  Wrench operator()(const Vec4& thrust, const BodyState& s) const { return (*this)(load(thrust), s); }
  Wrench operator()(const Load& load, const BodyState& s) const;

 private:
  Mat44 effectiveness_;
  Vec3 rotor_drag_;
  double mass_;
  double hover_thrust_per_rotor_;
};

}  // namespace sdlqr::sim
