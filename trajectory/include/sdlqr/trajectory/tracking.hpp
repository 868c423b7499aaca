#pragma once
// Choosing the reference on a sampled trajectory, at the controller's 100 Hz: spatial tracking
// (Algorithm 1 of the paper, §II-E) and temporal tracking, behind one small interface so the
// controller can switch at run time (PARAMS tracking field) without losing its place.
// Nothing here allocates after a trajectory is loaded.
//
// Both report the segment (i-1, i) and gamma in [0, 1] of the reference, with
//   x_des = x_{i-1} + gamma (x_i - x_{i-1}),  u_des = u_{i-1} + gamma (u_i - u_{i-1})
// (q_i taken in the hemisphere of q_{i-1}, the result renormalized).
//
// Spatial (Algorithm 1). The paper writes "repeat i <- i+1, d, gamma until gamma < 1"; run with i
// kept from the previous tick that would step at least one sample per tick, so each tick here
// first evaluates the segment it stopped on, then advances while gamma >= 1. Choices:
//  - i only moves forward: a vehicle held back or pushed backwards keeps its reference (the paper's
//    disturbance experiment, §III-C.4).
//  - gamma < 0 (the vehicle is behind the segment start: before the trajectory, or inside a corner
//    after passing it) is clamped to 0: the nearest point ahead on the path is sample i-1 itself.
//    Extrapolating backwards would hand out a point that is no longer on the remaining path.
//  - segments shorter than 1 um are skipped (gamma is undefined there).
//  - a non-finite position does not move i (the reference stays at sample i-1).
//  - end of an open trajectory: the last sample is held (gamma = 1, finished = true); it resumes
//    interpolating if the vehicle is pushed back behind the last sample (i still does not drop).
//  - closed trajectory: after the last segment i wraps to 1 and `lap` counts up; at most one lap
//    is advanced per tick (this also bounds the loop on degenerate paths).
//
// Temporal. The reference is the trajectory at time tau = now - start_time, clamped to the first
// sample before the start and to the last after the end (open), or wrapped into laps of period
// t_last - t_first (closed).
//
// A path that starts at rest (the paper's rest-to-rest min-snap) starts by the clock in either
// mode: Algorithm 1 alone leaves the reference on the first sample, at rest, until noise moves the
// vehicle past it (measured: 0.4 s for sdlqr, 2.4 s for sdlqr_integral, whose integral holds the
// vehicle on the reference). Until the path's first sample at kStartSpeed is due by the clock the
// spatial reference is the further along of Algorithm 1's and the temporal one, then Algorithm 1's
// alone (a path that starts moving has no such window).
//
// Switching keeps the place: entering temporal mode continues from the current reference's
// trajectory time (start_time becomes now - reference time), so the reference does not jump and
// then runs with the clock; entering spatial mode continues Algorithm 1 from the temporal
// reference's segment and lap.

#include <string>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/trajectory/validation.hpp"

namespace sdlqr::trajectory {

struct TrackingOutput {
  State x = State::Zero();  // reference state x_des
  Input u = Input::Zero();  // feed-forward input u_des
  int index = 1;            // i: the sample ahead, 1..n-1 (the REFERENCE index)
  double gamma = 0.0;       // [0, 1] between samples i-1 and i (the REFERENCE gamma)
  int lap = 0;              // completed laps of a closed trajectory
  double time = 0.0;        // [s] trajectory time of the reference, laps included
  bool finished = false;    // an open trajectory's last sample is being held
};

// Fills out.x and out.u with the interpolation of Algorithm 1's last line.
void interpolateSamples(const TrajectorySample& previous, const TrajectorySample& next, double gamma,
                        TrackingOutput& out);

class TrackingScheme {
 public:
  virtual ~TrackingScheme() = default;
  virtual ReferenceMode mode() const = 0;
  // The reference for a vehicle at `position` [m] at time `now` [s].
  virtual TrackingOutput update(double now, const Vec3& position) = 0;
  // Continue from a reference produced by either scheme, without a jump.
  virtual void resumeFrom(const TrackingOutput& reference, double now) = 0;
};

// Both schemes read a trajectory they do not own; it must be valid (validateTrajectory) and
// outlive them.
class SpatialTracker final : public TrackingScheme {
 public:
  explicit SpatialTracker(const Trajectory* trajectory = nullptr) : trajectory_(trajectory) {}
  ReferenceMode mode() const override { return ReferenceMode::kSpatial; }
  TrackingOutput update(double now, const Vec3& position) override;
  void resumeFrom(const TrackingOutput& reference, double now) override;
  void restart() { index_ = 1, lap_ = 0; }
  void rebind(const Trajectory* trajectory) { trajectory_ = trajectory; }

 private:
  const Trajectory* trajectory_;
  int index_ = 1;
  int lap_ = 0;
};

class TemporalTracker final : public TrackingScheme {
 public:
  explicit TemporalTracker(const Trajectory* trajectory = nullptr, double start_time = 0.0)
      : trajectory_(trajectory), start_time_(start_time) {}
  ReferenceMode mode() const override { return ReferenceMode::kTemporal; }
  TrackingOutput update(double now, const Vec3& position) override;
  void resumeFrom(const TrackingOutput& reference, double now) override;
  void setStartTime(double start_time) { start_time_ = start_time; }
  double startTime() const { return start_time_; }
  void rebind(const Trajectory* trajectory) { trajectory_ = trajectory; }
  // The reference at trajectory time tau [s].
  TrackingOutput at(double tau) const;

 private:
  const Trajectory* trajectory_;
  double start_time_;
};

// What the controller holds: the trajectory, both schemes and the active one.
class TrajectoryTracker {
 public:
  static constexpr double kStartSpeed = 0.1;  // [m/s] see "starts at rest" above

  TrajectoryTracker() = default;
  // The schemes point at the member trajectory: a copy's point at its own (the replay tries a
  // COMMAND on a copy of the controller). Not assignable.
  TrajectoryTracker(const TrajectoryTracker& other);
  TrajectoryTracker& operator=(const TrajectoryTracker&) = delete;

  // Validates and takes the trajectory (copies samples: call on receipt, not per tick); starts at
  // sample 0 in the trajectory's own tracking mode (spatial unless it says temporal). start_time
  // [s] is when temporal time 0 is. On error returns "sample k: reason" and keeps the previous one.
  std::string load(Trajectory trajectory, double start_time, const SampleChecks& checks = {});
  void clear() { loaded_ = false; }
  // Back to the first sample, temporal time 0 at start_time [s] (after an entry into the path).
  void restart(double start_time);
  bool loaded() const { return loaded_; }
  const Trajectory& trajectory() const { return trajectory_; }

  ReferenceMode mode() const { return active_->mode(); }
  // kSpatial or kTemporal; anything else returns false and changes nothing. Continues from the
  // last reference given out (see the header comment).
  bool setMode(ReferenceMode mode, double now);
  // Requires loaded().
  TrackingOutput update(double now, const Vec3& position);
  const TrackingOutput& lastReference() const { return last_; }

 private:
  Trajectory trajectory_;
  SpatialTracker spatial_{&trajectory_};
  TemporalTracker temporal_{&trajectory_};
  TrackingScheme* active_ = &spatial_;
  TrackingOutput last_;
  bool loaded_ = false;
  double start_time_ = 0.0;    // [s] temporal time 0 of the path (restart)
  double start_window_ = 0.0;  // [s] from it, until the path's first sample at kStartSpeed is due
};

}  // namespace sdlqr::trajectory
