#include "sdlqr/analysis/path_tracking.hpp"

#include <algorithm>
#include <cmath>

#include "flight_parts.hpp"
#include "sdlqr/analysis/trajectory_aborts.hpp"
#include "sdlqr/trajectory/tracking.hpp"

namespace sdlqr::analysis {

namespace {

using detail::seconds;

bool tracked(const Reference& r, int64_t seq) {
  return r.trajectory_seq == seq && (r.mode == ReferenceMode::kSpatial || r.mode == ReferenceMode::kTemporal);
}

bool hadEntry(const logger::FlightLog& log, int64_t seq) {
  for (const Reference& r : log.reference.messages) {
    if (r.trajectory_seq == seq && r.mode == ReferenceMode::kTransition) return true;
  }
  return false;
}

// Reference arc position over time, laps unrolled, never decreasing (Algorithm 1 only moves
// forward and temporal time only grows; a float wobble must not count as a lap).
struct Progress {
  std::vector<double> t;
  std::vector<double> arc;
  bool completed = false;
  double completed_at = 0.0;
};

Progress referenceProgress(const logger::FlightLog& log, const Trajectory& trajectory, const PathGeometry& path,
                           double completion_radius) {
  Progress p;
  const int last = static_cast<int>(trajectory.samples.size()) - 1;
  int lap = 0;
  int previous_index = -1;
  double running = 0.0;
  for (const Reference& r : log.reference.messages) {
    if (!tracked(r, trajectory.seq)) continue;
    const int index = std::clamp(static_cast<int>(r.index), 1, last);
    if (trajectory.closed && previous_index >= 0 && index < previous_index) ++lap;
    previous_index = index;
    const double arc = lap * path.length() + path.arcAt(index, std::clamp(r.gamma, 0.0, 1.0));
    running = std::max(running, arc);
    p.t.push_back(seconds(r.utime));
    p.arc.push_back(running);
    if (!trajectory.closed && !p.completed && running >= path.length() - completion_radius) {
      p.completed = true;
      p.completed_at = seconds(r.utime);
    }
  }
  return p;
}

// First time the (non-decreasing) reference arc reaches `arc`; `fallback` if it never does.
double timeReaching(const Progress& p, double arc, double fallback) {
  const auto it = std::lower_bound(p.arc.begin(), p.arc.end(), arc);
  return it == p.arc.end() ? fallback : p.t[static_cast<size_t>(it - p.arc.begin())];
}

double percent(int64_t part, int64_t whole) {
  return whole > 0 ? 100.0 * static_cast<double>(part) / static_cast<double>(whole) : 0.0;
}

// The report's window and progress: start, end, completion and laps, before any figure of the flight.
PathTrackingReport trackingWindow(const logger::FlightLog& log, const Trajectory& trajectory, const PathGeometry& path,
                                  const Progress& progress) {
  PathTrackingReport r;
  r.trajectory_seq = trajectory.seq;
  r.tracking = trajectory.tracking;
  r.closed = trajectory.closed;
  r.samples = static_cast<int>(trajectory.samples.size());
  r.path_length = path.length();
  r.duration = trajectory.samples.back().t - trajectory.samples.front().t;
  r.start = seconds(trajectory.start_utime > 0 ? trajectory.start_utime : trajectory.utime);
  // A path entered through a transition is judged from where the entry handed over to it.
  if (hadEntry(log, trajectory.seq)) {
    r.entry_time = progress.t.front() - r.start;
    r.start = progress.t.front();
  }
  r.completed = progress.completed;
  r.end = progress.completed ? progress.completed_at : progress.t.back();
  if (progress.completed) r.completion_time = progress.completed_at - r.start;
  r.laps = path.length() > 0.0 ? progress.arc.back() / path.length() : 0.0;
  if (!trajectory.closed) r.remaining = std::max(0.0, path.length() - progress.arc.back());
  return r;
}

// The truth's distance to the path at each of its times in the window, kept for the pulls.
struct PathDistances {
  std::vector<double> t;
  std::vector<double> distance;
};

std::vector<SimTruth>::const_iterator firstTruthAt(const std::vector<SimTruth>& truth, double from) {
  return std::lower_bound(truth.begin(), truth.end(), from,
                          [](const SimTruth& s, double t) { return seconds(s.utime) < t; });
}

// Errors over the truth in the window: to the path (where the vehicle flew) and to the temporal
// schedule (when it got there).
PathDistances measureErrors(const std::vector<SimTruth>& truth, const Trajectory& trajectory, const PathGeometry& path,
                            PathTrackingReport& r) {
  const trajectory::TemporalTracker schedule(&trajectory, r.start);
  PathDistances d;
  Vec3 sum_axis = Vec3::Zero();
  double sum = 0.0, sum_time = 0.0;
  for (auto it = firstTruthAt(truth, r.start); it != truth.end() && seconds(it->utime) <= r.end; ++it) {
    const double t = seconds(it->utime);
    const PathGeometry::Closest c = path.closest(it->position);
    const Vec3 axis = it->position - c.point;
    sum += c.distance * c.distance;
    sum_axis += axis.cwiseAbs2();
    r.path_error_max = std::max(r.path_error_max, c.distance);
    r.path_error_max_axis = r.path_error_max_axis.cwiseMax(axis.cwiseAbs());
    const double time_error = (it->position - position(schedule.at(t - r.start).x)).norm();
    sum_time += time_error * time_error;
    r.time_error_max = std::max(r.time_error_max, time_error);
    d.t.push_back(t);
    d.distance.push_back(c.distance);
  }
  r.truth_samples = static_cast<int64_t>(d.t.size());
  if (r.truth_samples > 0) {
    const double n = static_cast<double>(r.truth_samples);
    r.path_error_rms = std::sqrt(sum / n);
    r.path_error_rms_axis = (sum_axis / n).cwiseSqrt();
    r.time_error_rms = std::sqrt(sum_time / n);
  }
  return d;
}

// Skipped samples: every sample the reference went past, laps unrolled; a sample is visited when
// the truth came within skip_radius while the reference was within skip_window of it.
void findSkippedSamples(const std::vector<SimTruth>& truth, const Trajectory& trajectory, const PathGeometry& path,
                        const Progress& progress, const PathTrackingOptions& options, PathTrackingReport& r) {
  const double reached = progress.arc.back();
  const int per_lap = trajectory.closed ? r.samples - 1 : r.samples;
  const int laps = trajectory.closed ? static_cast<int>(std::floor(reached / path.length())) + 1 : 1;
  for (int lap = 0; lap < laps; ++lap) {
    for (int k = 0; k < per_lap; ++k) {
      const double arc = lap * path.length() + path.arcOf(k);
      if (arc <= 0.0 || arc > reached + 1e-9) continue;
      ++r.samples_passed;
      const double from = timeReaching(progress, arc - options.skip_window, r.start);
      const double to = timeReaching(progress, arc + options.skip_window, r.end);
      double nearest = std::numeric_limits<double>::infinity();
      for (auto it = firstTruthAt(truth, from); it != truth.end() && seconds(it->utime) <= to; ++it) {
        nearest = std::min(nearest, (it->position - path.point(k)).norm());
      }
      if (nearest <= options.skip_radius) {
        r.worst_visit = std::max(r.worst_visit, nearest);
      } else {
        r.skipped.push_back({lap, k, arc, nearest});
      }
    }
  }
}

// Commands in the window: saturation shares and thrust demands outside the vehicle's range.
void countCommands(const logger::FlightLog& log, const PathTrackingOptions& options, PathTrackingReport& r) {
  int64_t any = 0, rate = 0, thrust = 0;
  for (const RateCommand& c : log.rate_command.messages) {
    const double t = seconds(c.utime);
    if (t < r.start || t > r.end) continue;
    ++r.commands;
    any += c.saturated != 0 ? 1 : 0;
    rate += (c.saturated & 1) ? 1 : 0;
    thrust += (c.saturated & 2) ? 1 : 0;
    if (detail::thrustDemandOutside(c, options.thrust_min, options.thrust_max)) ++r.thrust_violations;
    if (!std::isfinite(c.thrust)) continue;
    r.thrust_min = std::isfinite(r.thrust_min) ? std::min(r.thrust_min, c.thrust) : c.thrust;
    r.thrust_max = std::isfinite(r.thrust_max) ? std::max(r.thrust_max, c.thrust) : c.thrust;
  }
  r.saturation_percent = percent(any, r.commands);
  r.rate_saturation_percent = percent(rate, r.commands);
  r.thrust_saturation_percent = percent(thrust, r.commands);
}

// One pull, judged from its start until the next pull's start (or the window's end): its largest
// distance to the path and when, after release, the truth came back within return_error for good.
PathPull measurePull(const Disturbance& d, double until, const PathDistances& path_distance, double return_error) {
  PathPull pull;
  pull.start = seconds(d.start_utime > 0 ? d.start_utime : d.utime);
  pull.release = pull.start + d.duration;
  double last_above = -1.0, last_t = pull.release;
  bool after_release = false, released_seen = false;
  for (size_t k = 0; k < path_distance.t.size(); ++k) {
    const double t = path_distance.t[k];
    const double distance = path_distance.distance[k];
    if (t < pull.start || t > until) continue;
    pull.max_distance = std::max(pull.max_distance, distance);
    if (t < pull.release) continue;
    if (!released_seen) pull.distance_at_release = distance;
    released_seen = true;
    after_release = true;
    last_t = t;
    if (distance >= return_error) last_above = last_t;
  }
  if (after_release && last_above < last_t) pull.return_time = last_above < 0.0 ? 0.0 : last_above - pull.release;
  return pull;
}

// Pulls inside the window.
void measurePulls(const logger::FlightLog& log, const PathDistances& path_distance, double return_error,
                  PathTrackingReport& r) {
  std::vector<const Disturbance*> pulls;
  int64_t last_seq = -1;
  for (const Disturbance& d : log.disturbance.messages) {
    const double t = seconds(d.start_utime > 0 ? d.start_utime : d.utime);
    const bool resent = d.seq == last_seq;  // sdlqr-mission's re-send: the same pull, wherever its first copy fell
    last_seq = d.seq;
    if (t >= r.start && t < r.end && !resent) pulls.push_back(&d);
  }
  for (size_t i = 0; i < pulls.size(); ++i) {
    const double until = i + 1 < pulls.size() ? seconds(pulls[i + 1]->start_utime) : r.end;
    r.pulls.push_back(measurePull(*pulls[i], until, path_distance, return_error));
  }
}

}  // namespace

PathGeometry::PathGeometry(const Trajectory& trajectory) {
  points_.reserve(trajectory.samples.size());
  arc_.reserve(trajectory.samples.size());
  for (const TrajectorySample& s : trajectory.samples) {
    const Vec3 p = position(s.x);
    arc_.push_back(points_.empty() ? 0.0 : arc_.back() + (p - points_.back()).norm());
    points_.push_back(p);
  }
  if (points_.empty()) {
    points_.push_back(Vec3::Zero());
    arc_.push_back(0.0);
  }
}

PathGeometry::Closest PathGeometry::closest(const Vec3& position) const {
  Closest best;
  best.point = points_[0];
  best.distance = (position - points_[0]).norm();
  for (size_t k = 1; k < points_.size(); ++k) {
    const Vec3 a = points_[k - 1];
    const Vec3 segment = points_[k] - a;
    const double length2 = segment.squaredNorm();
    const double gamma = length2 > 0.0 ? std::clamp((position - a).dot(segment) / length2, 0.0, 1.0) : 0.0;
    const Vec3 point = a + gamma * segment;
    const double distance = (position - point).norm();
    if (distance < best.distance) {
      best.point = point;
      best.distance = distance;
      best.arc = arc_[k - 1] + gamma * (arc_[k] - arc_[k - 1]);
    }
  }
  return best;
}

double PathGeometry::arcAt(int index, double gamma) const {
  const int last = static_cast<int>(points_.size()) - 1;
  if (last < 1) return 0.0;
  index = std::clamp(index, 1, last);
  const size_t i = static_cast<size_t>(index);
  return arc_[i - 1] + gamma * (arc_[i] - arc_[i - 1]);
}

std::vector<PathTrackingReport> analyzePathTracking(const logger::FlightLog& log, const PathTrackingOptions& options) {
  std::vector<PathTrackingReport> reports;
  const auto& truth = log.sim_truth.messages;
  for (const Trajectory& trajectory : log.trajectory.messages) {
    if (trajectory.samples.size() < 2) continue;
    const PathGeometry path(trajectory);
    const Progress progress = referenceProgress(log, trajectory, path, options.completion_radius);
    if (progress.t.empty()) continue;  // rejected or never tracked

    PathTrackingReport r = trackingWindow(log, trajectory, path, progress);
    r.aborted_at = trajectoryAbortTime(log, trajectory.seq);
    const PathDistances path_distance = measureErrors(truth, trajectory, path, r);
    findSkippedSamples(truth, trajectory, path, progress, options, r);
    countCommands(log, options, r);
    measurePulls(log, path_distance, options.return_error, r);
    reports.push_back(std::move(r));
  }
  return reports;
}

}  // namespace sdlqr::analysis
