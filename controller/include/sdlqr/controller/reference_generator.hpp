#pragma once
// Chooses the reference (x0, u0) of each controller tick: idle on the ground, a take-off ramp,
// a held setpoint (reference jumps of Fig. 5 are setpoint changes), a tracked trajectory, or a
// landing ramp. Clock-free: time is the state estimate's utime.
//
// Trajectories are joined and left within the lqr limits (transition_reference.hpp): the first
// tick after a TRAJECTORY plans an entry from the vehicle's state to the path's first sample
// (none when the vehicle is already there), flown by the clock (REFERENCE mode TRANSITION) before
// the path is tracked from its start; a GOTO or LAND while tracking, or the end of an open path
// still moving, plans an exit to rest (the GOTO's position, or where the vehicle can stop) before
// the hold or the landing. A trajectory whose entry no duration makes flyable is not flown (held
// where the vehicle is, counted). The guard (trajectory/guard.hpp) watches the path and both
// transitions; a trip levels and stops the vehicle, then holds where it stopped (as a rejoin).
//
// Rejoining: a generator whose first initialised estimate shows the vehicle airborne (a controller
// restarted mid-flight while the lowlevel's failsafe holds the vehicle level) holds where the
// vehicle is instead of idling; the mission's re-sent TAKEOFF or GOTO then restores the setpoint.
// A rejoin on a vehicle tilted or moving (an airborne start, a throw) first recovers: the reference
// is the vehicle's own position, level and at rest, so the law only rights and stops it; once it is
// within recovery_tilt_deg and recovery_speed the hold is set there (as ArduPilot's Throw mode
// uprights, then holds). Chasing the point first seen instead flies back metres the vehicle was
// thrown while righting itself, tilted all the way.

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/controller/transition_reference.hpp"
#include "sdlqr/trajectory/feasibility.hpp"
#include "sdlqr/trajectory/tracking.hpp"

namespace sdlqr::controller {

// kTrajectory includes its entry; kExit is the transition from a trajectory to a hover.
enum class FlightPhase { kIdle, kTakeoff, kHold, kTrajectory, kExit, kLanding };

const char* toString(FlightPhase phase);

class ReferenceGenerator {
 public:
  ReferenceGenerator(const ControllerParams& params, double gravity);

  void handleCommand(const Command& command);
  // Starts tracking a trajectory (copied once here, never in the 100 Hz path) if flying and its
  // samples are within the limits (thrust in [c_min, c_max], ||omega|| <= omega_max, speed within
  // the guard's, trajectory/feasibility.hpp), or, beyond them with trajectory_beyond_limits: scale,
  // time-scaled to its highest feasible speed (trajectory/speed_fit.hpp; the bisection runs here, on
  // receipt). Returns an empty string when accepted, else why not.
  std::string setTrajectory(const Trajectory& trajectory, int64_t now_utime);
  // Switches spatial <-> temporal tracking without losing the place (PARAMS tracking field).
  bool setTrackingMode(ReferenceMode mode, int64_t now_utime);
  void setParams(const ControllerParams& params) { params_ = params; }
  // The input limits transitions are planned within (lqr c_min, c_max, omega_max, gravity).
  void setLimits(const LqrParams& lqr);

  // Advances the phase with the estimate and fills `out` (x, u, mode, index, gamma, trajectory_seq).
  // Returns false while idle (nothing to command).
  bool update(const StateEstimate& estimate, Reference& out);

  FlightPhase phase() const { return phase_; }
  // True from a rejoin until the next command: a TAKEOFF then sets the held height above the ground.
  bool rejoined() const { return rejoined_; }
  // True from a rejoin until the vehicle is level and stopped (or a GOTO, LAND or DISARM).
  bool recovering() const { return recovering_; }
  const trajectory::TrajectoryTracker& tracker() const { return tracker_; }
  // Trajectories aborted into a hold by the guard (trajectory/guard.hpp), and why the last was.
  int64_t guardAborts() const { return guard_aborts_; }
  trajectory::GuardTrip lastGuardTrip() const { return last_guard_trip_; }
  // Transitions planned (entries and exits), and trajectories refused for want of a flyable entry.
  int64_t transitions() const { return transitions_; }
  int64_t entriesRefused() const { return entries_refused_; }
  // Uploads flown time-scaled, and the last one's fit ("at 4 m/s the path is beyond ...; feasible up to 3.5 m/s").
  int64_t trajectoriesScaled() const { return trajectories_scaled_; }
  const std::string& lastScaling() const { return last_scaling_; }
  const TransitionReference& transition() const { return transition_; }

 private:
  std::string loadTrajectory(const Trajectory& trajectory, int64_t now_utime);
  std::string loadScaled(const Trajectory& trajectory, const trajectory::FeasibilityLimits& limits,
                         int64_t now_utime);
  void startTakeoff(const StateEstimate& estimate, double height);
  void hold(const Vec3& position, double yaw);
  bool landedAt(const StateEstimate& estimate);
  void rejoin(const StateEstimate& estimate);
  Vec3 recoveryReference(const StateEstimate& estimate);
  bool trackTrajectory(const StateEstimate& estimate, Reference& out);
  bool flyExit(const StateEstimate& estimate, Reference& out);
  void beginEntry(const StateEstimate& estimate, double now_s);
  // An exit from the last reference: to rest at `hold` (nullptr: a stop), then `then`.
  bool beginExit(const Vec3* hold, double yaw, FlightPhase then);
  // Beyond the guard: recover (level, stop) and hold where the vehicle stops. True if it tripped.
  // The attitude judged is the one flown: with lqr.model_rotor_drag, (reference, input) remapped.
  bool guardTrips(const StateEstimate& estimate, const State& reference, const Input& input);
  void emit(Reference& out, const State& x, const Input& u, ReferenceMode mode, int index, double gamma,
            int64_t trajectory_seq);

  ControllerParams params_;
  double gravity_;
  LqrParams lqr_;
  FlightPhase phase_ = FlightPhase::kIdle;
  bool takeoff_pending_ = false;
  bool landing_pending_ = false;  // LAND received: the ramp starts at the next tick
  double pending_takeoff_height_ = 1.0;
  Vec3 setpoint_ = Vec3::Zero();
  double yaw_ = 0.0;
  Vec3 ramp_position_ = Vec3::Zero();
  double ramp_target_z_ = 0.0;
  double ground_z_ = 0.0;
  bool seen_estimate_ = false;  // an initialised estimate has reached update()
  bool rejoined_ = false;
  bool recovering_ = false;
  bool recovery_keeps_height_ = false;  // the held height came from a TAKEOFF: kept at the hold
  int64_t last_utime_ = -1;
  int64_t landed_since_utime_ = -1;
  trajectory::TrajectoryTracker tracker_;
  int64_t trajectory_seq_ = -1;
  double path_speed_ = 0.0;  // [m/s] the top speed of the last trajectory loaded (its transitions')
  int64_t guard_aborts_ = 0;
  trajectory::GuardTrip last_guard_trip_ = trajectory::GuardTrip::kNone;
  TransitionReference transition_;
  bool entry_pending_ = false;  // a trajectory was loaded: its entry is planned at the next tick
  bool entering_ = false;       // flying the entry of the trajectory loaded
  FlightPhase after_exit_ = FlightPhase::kHold;  // kHold (at the exit's end) or kLanding
  State last_x_ = State::Zero();  // the reference of the last tick (an exit's acceleration)
  Input last_u_ = Input::Zero();
  Vec3 last_estimate_position_ = Vec3::Zero();  // the vehicle at the last tick (where an exit starts)
  Vec3 last_estimate_velocity_ = Vec3::Zero();
  int64_t transitions_ = 0;
  int64_t entries_refused_ = 0;
  int64_t trajectories_scaled_ = 0;
  std::string last_scaling_;
};

}  // namespace sdlqr::controller
