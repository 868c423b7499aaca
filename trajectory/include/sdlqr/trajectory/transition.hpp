#pragma once
// Joining and leaving a trajectory within the vehicle's limits. A path that starts at speed (a
// circle) flown from a hover asks for a velocity step at its first sample; a GOTO while flying it
// asks for a step back to rest. Both became the largest errors of a fast path (issue 25: a circle
// the feasibility check accepted crashed at its entry). A transition replaces each step with a
// flyable motion:
//
//   entry  from the vehicle's state (position, velocity, acceleration) to the path's first sample
//          (position, velocity, acceleration, jerk, heading), then the path;
//   exit   from the reference's state to rest at a hover point (a GOTO's position, or where the
//          vehicle can stop for a LAND), then the hold or the landing.
//
// Each is a degree-7 polynomial per axis matching position and its first three derivatives at
// both ends (a stop: velocity, acceleration and jerk zero at a free end position) (so the flat map gives continuous attitude and body rates, flatness.hpp), heading by a
// quintic blend, and the shortest duration on a stepping-then-bisection search whose every point
// of a fine grid keeps c in [c_min, c_max], ||omega|| <= omega_max (the inputs flown against the
// model's rotor drag, feasibility.hpp) and the speed within the larger
// of the two ends' speeds and `min_speed_limit`, plus `speed_margin` (feasibility.hpp) — and
// within `input_fraction` of omega_max and c_max where its ends allow: the feedback needs room
// around the reference (a transition at omega_max left the vehicle none and it diverged at 9 m/s). A transition found is flyable
// by construction; none is found only beyond `max_duration`. Planned first within `gentle_fraction`
// where that finds one: the shortest transition within 80 % of an agile vehicle's limits tilts 50
// degrees in 0.2 s, which a hover LQR does not follow (docs/agility.md §5). Where neither finds one,
// the speed bound is raised to the path's top speed, and, for an exit, last the full limits are
// used: a stop from where a path accelerates hard, or turns near the limits, cannot brake at once
// (transition.cpp).
//
// Fixed-size and allocation-free: the controller plans a transition inside a tick.

#include <string>

#include "sdlqr/config/param_table.hpp"
#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/feasibility.hpp"
#include "sdlqr/trajectory/flatness.hpp"

namespace sdlqr::trajectory {

// Settings of the transitions (section `controller.transition`); the input limits are lqr's.
struct TransitionParams {
  bool enabled;                // false: the old steps (a path entered at full speed, a GOTO jumps)
  double max_duration;         // [s] longest transition searched
  double min_speed_limit;      // [m/s] speed bound when both ends are slower
  double speed_margin;         // [-] a transition may exceed the faster end's speed by this fraction
  double input_fraction;       // [-] of omega_max and c_max a transition uses (unless its ends need more)
  double gentle_fraction;      // [-] of omega_max and c_max tried first (below input_fraction)
  double position_tolerance;   // [m] closer than this (and the next two) to the path's start: no entry
  double velocity_tolerance;   // [m/s]
  double acceleration_tolerance;  // [m/s^2]

  TransitionParams();
  static const ParamTable<TransitionParams>& declaration();
};

// Position and heading with the derivatives a transition matches at its ends.
struct FlatState {
  Vec3 position = Vec3::Zero();
  Vec3 velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 jerk = Vec3::Zero();
  double yaw = 0.0;  // [rad]
};

// The flat state of a reference (state x, input u): acceleration c z_b - g e_z, jerk from the body
// rates and `thrust_rate` [m/s^3] (c' z_b + c (omega_y x_b - omega_x y_b)).
FlatState flatStateOf(const State& x, const Input& u, double thrust_rate, double gravity);
// The flat state at a trajectory's first sample (its thrust rate from the second).
FlatState flatStateAtStart(const Trajectory& trajectory, double gravity);

class Transition {
 public:
  // The polynomial from `from` to `to` in `duration` [s] (> 0).
  static Transition between(const FlatState& from, const FlatState& to, double duration);
  // From `from` to rest in `duration`, where the least snap stops (its end position is free: the
  // s^7 coefficient is zero), heading kept.
  static Transition stopping(const FlatState& from, double duration);
  // The flat output at t [s] from its start, clamped to [0, duration].
  FlatOutput at(double t) const;
  double duration() const { return duration_; }

 private:
  void setStart(const FlatState& from, double duration);
  Vec3 startPart(int order) const;

  Eigen::Matrix<double, 3, 8> coefficients_ = Eigen::Matrix<double, 3, 8>::Zero();  // of s = t / duration
  double duration_ = 1.0;
  double yaw_start_ = 0.0;
  double yaw_change_ = 0.0;
};

struct TransitionPlan {
  bool found = false;
  Transition transition;         // valid when found
  FeasibilityReport report;      // of the transition found, or of the longest tried
  FeasibilityLimits limits;      // it was judged against
};

// What a transition is for. An entry that finds none is refused (the vehicle holds where it is: a
// transition at the full limits leaves the feedback no room, and an entry planned so diverged at
// 9 m/s); an exit that finds none leaves the reference to jump, so it is searched last within them.
enum class TransitionKind { kEntry, kExit };

// The shortest flyable transition between the two states (from its start at rest in `to` for an
// exit: `to` as given). `path_speed` [m/s]: the top speed of the path it joins or leaves; where no
// transition is found within the speed bound of its ends, one within the path's (plus speed_margin) is
// searched (a stop from a slow sample that accelerates hard gains speed before it can brake).
TransitionPlan planTransition(const FlatState& from, const FlatState& to, const LqrParams& lqr,
                              const TransitionParams& params, double path_speed = 0.0,
                              TransitionKind kind = TransitionKind::kEntry);
// The shortest flyable stop (Transition::stopping), heading kept, an exit; `path_speed` as above.
TransitionPlan planStop(const FlatState& from, const LqrParams& lqr, const TransitionParams& params,
                        double path_speed = 0.0);
// Whether planStop finds a stop (the first flyable duration, not the shortest: a fifth of the work).
bool stopExists(const FlatState& from, const LqrParams& lqr, const TransitionParams& params, double path_speed);
// The same, trying `duration_hint` [s] first: a duration the search found from a neighbouring
// sample (0: none), set to the one found here. The search tries the same durations from any start,
// so where the hint is flyable it would find one too: the answer is the same, a third cheaper.
bool stopExists(const FlatState& from, const LqrParams& lqr, const TransitionParams& params, double path_speed,
                double& duration_hint);

// True when `from` is within the tolerances of `to`: flying the path from there needs no entry.
bool closeEnough(const FlatState& from, const FlatState& to, const TransitionParams& params);

// Feasibility of a transition on its grid (points evenly spaced over its duration, ends included).
FeasibilityReport checkFeasibility(const Transition& transition, const FeasibilityLimits& limits, double gravity);

// "entry 1.23 s: max thrust 14.1 m/s^2, max |omega| 1.87 rad/s, max speed 3.25 m/s" or why none.
std::string describeTransition(const char* what, const TransitionPlan& plan);

}  // namespace sdlqr::trajectory
