#pragma once
// Chooses the reference (x0, u0) of each controller tick: idle on the ground, a take-off ramp,
// a held setpoint (reference jumps of Fig. 5 are setpoint changes), a tracked trajectory, or a
// landing ramp. Clock-free: time is the state estimate's utime.
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
#include "sdlqr/trajectory/tracking.hpp"

namespace sdlqr::controller {

enum class FlightPhase { kIdle, kTakeoff, kHold, kTrajectory, kLanding };

const char* toString(FlightPhase phase);

class ReferenceGenerator {
 public:
  ReferenceGenerator(const ControllerParams& params, double gravity);

  void handleCommand(const Command& command);
  // Starts tracking a trajectory (copied once here, never in the 100 Hz path) if flying. Returns
  // an empty string when accepted, else why not.
  std::string setTrajectory(const Trajectory& trajectory, int64_t now_utime);
  // Switches spatial <-> temporal tracking without losing the place (PARAMS tracking field).
  bool setTrackingMode(ReferenceMode mode, int64_t now_utime);
  void setParams(const ControllerParams& params) { params_ = params; }

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

 private:
  void startTakeoff(const StateEstimate& estimate, double height);
  void hold(const Vec3& position, double yaw);
  bool landedAt(const StateEstimate& estimate);
  bool followTrajectory(const StateEstimate& estimate, Reference& out);
  void rejoin(const StateEstimate& estimate);
  Vec3 recoveryReference(const StateEstimate& estimate);

  ControllerParams params_;
  double gravity_;
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
  int64_t guard_aborts_ = 0;
  trajectory::GuardTrip last_guard_trip_ = trajectory::GuardTrip::kNone;
};

}  // namespace sdlqr::controller
