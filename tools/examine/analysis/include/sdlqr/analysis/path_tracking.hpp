#pragma once
// How a flight followed an uploaded trajectory (paper §III-C.2-4, Fig. 7-9): the distance to the
// closest point of the path, the error to the time-indexed reference, completion, segments the
// reference skipped, input saturation and thrust.
//
// The path is the polyline through the trajectory's samples (a closed trajectory repeats it lap
// after lap). Positions are SIM_TRUTH. The window of a trajectory runs from its start until the
// reference reaches the last sample (open) or until the controller stops publishing references
// of it (a later GOTO or LAND); see completion_radius. A path entered through a transition
// (REFERENCE mode TRANSITION, controller/reference_generator.hpp) starts where the entry ends.
//
// Skipped samples. The controller's REFERENCE (index i, gamma) unrolled over laps gives the
// reference's arc position s_ref(t). A sample at arc position s_k the reference has passed is
// skipped when the vehicle never came within `skip_radius` of it while the reference was within
// `skip_window` of path before or after it (the window keeps later laps over the same points from
// counting as a visit).

#include <limits>
#include <string>
#include <vector>

#include "sdlqr/messages/messages.hpp"
#include "sdlqr/logger/flight_log.hpp"

namespace sdlqr::analysis {

struct PathTrackingOptions {
  double skip_radius = 0.3;         // [m] a sample the vehicle came this close to was visited
  double skip_window = 3.0;         // [m] of path either side of a sample where a visit counts
  double return_error = 0.10;       // [m] distance to the path counted as back on it after a pull
  // [m] an open trajectory is complete once the reference is this close to its end along the
  // path: spatial tracking of a rest-to-rest trajectory approaches the last sample asymptotically
  // (the feed-forward speed goes to zero with the vehicle's own progress).
  double completion_radius = 0.05;
  double thrust_min = -std::numeric_limits<double>::infinity();  // [m/s^2] LqrParams c_min
  double thrust_max = std::numeric_limits<double>::infinity();   // [m/s^2] LqrParams c_max
};

// The polyline through a trajectory's samples, with arc length.
class PathGeometry {
 public:
  explicit PathGeometry(const Trajectory& trajectory);

  struct Closest {
    Vec3 point = Vec3::Zero();  // [m] on the path
    double arc = 0.0;           // [m] arc position of `point` within one lap
    double distance = 0.0;      // [m]
  };
  // Closest point on the whole path (brute force over the segments: a few hundred).
  Closest closest(const Vec3& position) const;
  // Arc position [m] of the reference at segment (index-1, index) and gamma, within one lap.
  double arcAt(int index, double gamma) const;

  int samples() const { return static_cast<int>(points_.size()); }
  const Vec3& point(int k) const { return points_[static_cast<size_t>(k)]; }
  double arcOf(int k) const { return arc_[static_cast<size_t>(k)]; }
  double length() const { return arc_.back(); }

 private:
  std::vector<Vec3> points_;
  std::vector<double> arc_;
};

// A pull (DISTURBANCE) that happened while a trajectory was tracked.
struct PathPull {
  std::string label;                 // the scenario's pull (set by analyzeFlight)
  std::string missing;               // why it has no figures: its DISTURBANCE not in the log, or
                                     // played after the trajectory's window
  double start = 0.0;                // [s]
  double release = 0.0;              // [s]
  double max_distance = 0.0;         // [m] largest distance to the path from start to window end
  double distance_at_release = 0.0;  // [m]
  // [s] after release, the distance to the path stays below return_error until the window end
  // (or the next pull); NaN if it never does.
  double return_time = std::numeric_limits<double>::quiet_NaN();
};

struct SkippedSample {
  int lap = 0;
  int index = 0;             // sample index within the lap
  double arc = 0.0;          // [m] unrolled arc position
  double closest = 0.0;      // [m] nearest approach of the vehicle inside the window
};

struct PathTrackingReport {
  std::string label;                 // the scenario event's label (set by analyzeFlight)
  std::string missing;               // why the scenario's trajectory has no figures (not in the
                                     // log, or never tracked); empty when it was flown
  int64_t trajectory_seq = -1;
  ReferenceMode tracking = ReferenceMode::kSpatial;  // as uploaded
  bool closed = false;
  int samples = 0;
  double path_length = 0.0;          // [m] one lap of the polyline
  double duration = 0.0;             // [s] trajectory time of the last sample
  double start = 0.0;                // [s] simulation time the path started (after its entry)
  double entry_time = 0.0;           // [s] from the upload to the path: the entry's duration (0: none)
  double end = 0.0;                  // [s] end of the analysed window
  bool completed = false;            // the reference came within completion_radius of the end (open)
  double completion_time = std::numeric_limits<double>::quiet_NaN();  // [s] after start
  double remaining = 0.0;            // [m] of path the reference had left at the window end (open)
  double laps = 0.0;                 // [-] reference progress over one lap's length
  double aborted_at = std::numeric_limits<double>::quiet_NaN();  // [s] the guard aborted the path
                                     // into a hold (NaN: it did not): the figures are of the part
                                     // flown, and every check of the path fails

  int64_t truth_samples = 0;
  double path_error_rms = 0.0;       // [m] distance to the closest point of the path
  double path_error_max = 0.0;
  Vec3 path_error_rms_axis = Vec3::Zero();  // [m] per axis of (position - closest point)
  Vec3 path_error_max_axis = Vec3::Zero();
  double time_error_rms = 0.0;       // [m] to the trajectory at (t - start)
  double time_error_max = 0.0;

  int samples_passed = 0;            // samples the reference went past (laps unrolled)
  std::vector<SkippedSample> skipped;
  double worst_visit = 0.0;          // [m] largest nearest approach among visited samples

  int64_t commands = 0;              // RATE_CMD in the window
  double saturation_percent = 0.0;   // [%] commands with any clipping
  double rate_saturation_percent = 0.0;
  double thrust_saturation_percent = 0.0;
  double thrust_min = std::numeric_limits<double>::quiet_NaN();  // [m/s^2] commanded
  double thrust_max = std::numeric_limits<double>::quiet_NaN();
  int64_t thrust_violations = 0;     // thrust demands (before the controller's clip) outside [thrust_min, thrust_max], or NaN

  std::vector<PathPull> pulls;
};

// One report per TRAJECTORY message the controller tracked (has REFERENCE with its seq).
std::vector<PathTrackingReport> analyzePathTracking(const logger::FlightLog& log,
                                                    const PathTrackingOptions& options = {});

}  // namespace sdlqr::analysis
