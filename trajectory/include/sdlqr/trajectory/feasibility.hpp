#pragma once
// Is a reference flyable within the controller's limits? Top speed against v_max, and the
// flatness inputs against the LQR input limits: c in [c_min, c_max], ||omega|| <= omega_max. The
// inputs judged are those the controller flies: with the model's rotor drag (lqr.model_rotor_drag,
// limits.drag) each point's reference remapped through the flat map with drag
// (drag_feedforward.hpp flownInput), as given without.
//
// For a min-snap polynomial the inputs are exact (flatness) on a fine grid. For a sampled
// trajectory (CSV, the ellipse) the samples' own inputs are checked, plus whether they agree with
// the motion they are meant to produce: the acceleration the velocities demand between two
// samples, (v_i - v_{i-1}) / dt, against the one the inputs give, the mean of c z_b(q) - g e_z
// at both samples. A hand-made reference (the paper's ellipse) fails this: its inputs are those
// of hover while it turns.

#include <limits>
#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/trajectory/min_snap.hpp"

namespace sdlqr::trajectory {

struct FeasibilityLimits {
  double v_max = 3.0;               // [m/s]
  double c_min = 2.0;               // [m/s^2]
  double c_max = 18.0;              // [m/s^2]
  double omega_max = 2.0;           // [rad/s]
  double accel_mismatch_max = 0.5;  // [m/s^2] sampled trajectories only
  RotorDrag drag;                   // the controllers' model's (LqrParams::rotorDrag): none by default

  static FeasibilityLimits from(const LqrParams& lqr, double v_max, double accel_mismatch_max);
};

struct FeasibilityReport {
  double max_speed = 0.0;                                               // [m/s]
  double max_thrust = 0.0;                                              // [m/s^2]
  double min_thrust = std::numeric_limits<double>::infinity();          // [m/s^2]
  double max_body_rate = 0.0;                                           // [rad/s] max ||omega||
  double max_accel_mismatch = std::numeric_limits<double>::quiet_NaN();  // [m/s^2] NaN: not checked
  bool speed_ok = false;
  bool max_thrust_ok = false;
  bool min_thrust_ok = false;
  bool body_rate_ok = false;
  bool consistency_ok = true;  // true when not checked
  long points = 0;             // grid points or samples checked

  bool feasible() const { return speed_ok && max_thrust_ok && min_thrust_ok && body_rate_ok && consistency_ok; }
};

// The building blocks of every check: one reference point's speed and the inputs flown for it
// (flownInput against limits.drag) into the report's extremes, then the verdicts against the limits.
void accountSample(FeasibilityReport& report, const State& x, const Input& u, const FeasibilityLimits& limits,
                   double gravity);
void judgeReport(FeasibilityReport& report, const FeasibilityLimits& limits);

FeasibilityReport checkFeasibility(const MinSnapTrajectory& polynomial, const FeasibilityLimits& limits,
                                   double gravity, double grid_dt);
FeasibilityReport checkFeasibility(const Trajectory& trajectory, const FeasibilityLimits& limits, double gravity);

// The limits a report fails, "max |omega| 2.39 > 2 rad/s; max thrust 20.2 > 18 m/s^2;" (empty: none).
std::string describeViolations(const FeasibilityReport& report, const FeasibilityLimits& limits);

// A few lines "max speed  2.999 m/s  <= 3.000  pass" for the CLI.
std::string formatReport(const FeasibilityReport& report, const FeasibilityLimits& limits);

}  // namespace sdlqr::trajectory
