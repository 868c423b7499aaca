#include "sdlqr/trajectory/tracking.hpp"

#include <algorithm>
#include <cmath>

#include "sdlqr/math/quaternion.hpp"

namespace sdlqr::trajectory {

namespace {

constexpr double kZeroSegmentSquared = 1e-12;  // [m^2] (1 um): shorter segments are skipped

double lapPeriod(const Trajectory& trajectory) {
  return trajectory.samples.back().t - trajectory.samples.front().t;
}

// Reference on segment (index - 1, index) at gamma, with its trajectory time.
TrackingOutput referenceOn(const Trajectory& trajectory, int index, double gamma, int lap, bool finished) {
  const TrajectorySample& previous = trajectory.samples[index - 1];
  const TrajectorySample& next = trajectory.samples[index];
  TrackingOutput out;
  out.index = index;
  out.gamma = gamma;
  out.lap = lap;
  out.finished = finished;
  out.time = previous.t + gamma * (next.t - previous.t) + lap * lapPeriod(trajectory);
  interpolateSamples(previous, next, gamma, out);
  return out;
}

}  // namespace

void interpolateSamples(const TrajectorySample& previous, const TrajectorySample& next, double gamma,
                        TrackingOutput& out) {
  State next_x = next.x;
  orientation(next_x) = quat::sameHemisphere(orientation(next.x), orientation(previous.x));
  out.x = previous.x + gamma * (next_x - previous.x);
  orientation(out.x).normalize();
  out.u = previous.u + gamma * (next.u - previous.u);
}

TrackingOutput SpatialTracker::update(double /*now*/, const Vec3& p) {
  const Trajectory& trajectory = *trajectory_;
  const int last = static_cast<int>(trajectory.samples.size()) - 1;
  // A non-finite position must not run the index forward: stay at the segment start.
  if (!p.allFinite()) return referenceOn(trajectory, index_, 0.0, lap_, false);
  // When the step bound ends the loop, the reference is the start of the segment reached.
  double gamma = 0.0;
  bool finished = false;
  for (int steps = 0; steps <= last; ++steps, gamma = 0.0) {
    const Vec3 from = position(trajectory.samples[index_ - 1].x);
    const Vec3 d = position(trajectory.samples[index_].x) - from;
    const double length_squared = d.squaredNorm();
    gamma = length_squared <= kZeroSegmentSquared ? 1.0 : (p - from).dot(d) / length_squared;
    if (gamma < 1.0) break;
    if (index_ < last) {
      ++index_;
    } else if (trajectory.closed) {
      index_ = 1;
      ++lap_;
    } else {
      finished = true;
      break;
    }
  }
  return referenceOn(trajectory, index_, std::clamp(gamma, 0.0, 1.0), lap_, finished);
}

void SpatialTracker::resumeFrom(const TrackingOutput& reference, double /*now*/) {
  const int last = static_cast<int>(trajectory_->samples.size()) - 1;
  index_ = std::clamp(reference.index, 1, last);
  lap_ = std::max(0, reference.lap);
}

TrackingOutput TemporalTracker::at(double tau) const {
  const Trajectory& trajectory = *trajectory_;
  const auto& samples = trajectory.samples;
  const int last = static_cast<int>(samples.size()) - 1;
  const double first_t = samples.front().t;
  const double last_t = samples.back().t;
  if (!(tau > first_t)) return referenceOn(trajectory, 1, 0.0, 0, false);  // also catches NaN
  int lap = 0;
  double local = tau;
  if (trajectory.closed) {
    const double period = lapPeriod(trajectory);
    lap = static_cast<int>(std::floor((tau - first_t) / period));
    local = std::clamp(tau - lap * period, first_t, last_t);
  } else if (tau >= last_t) {
    return referenceOn(trajectory, last, 1.0, 0, true);
  }
  // First sample later than `local`: the segment's end.
  const auto after = std::upper_bound(samples.begin(), samples.end(), local,
                                      [](double t, const TrajectorySample& s) { return t < s.t; });
  const int index = std::clamp(static_cast<int>(after - samples.begin()), 1, last);
  const double gamma = (local - samples[index - 1].t) / (samples[index].t - samples[index - 1].t);
  TrackingOutput out = referenceOn(trajectory, index, std::clamp(gamma, 0.0, 1.0), lap, false);
  out.time = tau;
  return out;
}

TrackingOutput TemporalTracker::update(double now, const Vec3& /*position*/) { return at(now - start_time_); }

void TemporalTracker::resumeFrom(const TrackingOutput& reference, double now) { start_time_ = now - reference.time; }

TrajectoryTracker::TrajectoryTracker(const TrajectoryTracker& other)
    : trajectory_(other.trajectory_),
      spatial_(other.spatial_),
      temporal_(other.temporal_),
      active_(other.active_ == &other.spatial_ ? static_cast<TrackingScheme*>(&spatial_) : &temporal_),
      last_(other.last_),
      loaded_(other.loaded_),
      start_time_(other.start_time_),
      start_window_(other.start_window_) {
  spatial_.rebind(&trajectory_);
  temporal_.rebind(&trajectory_);
}

std::string TrajectoryTracker::load(Trajectory trajectory, double start_time, const SampleChecks& checks) {
  const std::string why = validateTrajectory(trajectory, checks);
  if (!why.empty()) return why;
  trajectory_ = std::move(trajectory);
  // One hemisphere along the path, so neighbouring samples interpolate the short way.
  for (std::size_t k = 1; k < trajectory_.samples.size(); ++k) {
    State& x = trajectory_.samples[k].x;
    orientation(x) = quat::sameHemisphere(orientation(x), orientation(trajectory_.samples[k - 1].x));
  }
  active_ = trajectory_.tracking == ReferenceMode::kTemporal ? static_cast<TrackingScheme*>(&temporal_)
                                                              : static_cast<TrackingScheme*>(&spatial_);
  restart(start_time);
  loaded_ = true;
  return {};
}

void TrajectoryTracker::restart(double start_time) {
  spatial_.restart();
  temporal_.setStartTime(start_time);
  start_time_ = start_time;
  last_ = referenceOn(trajectory_, 1, 0.0, 0, false);
  // The start by the clock lasts until the path's first sample at kStartSpeed is due.
  start_window_ = 0.0;
  for (const TrajectorySample& s : trajectory_.samples) {
    start_window_ = s.t - trajectory_.samples.front().t;
    if (velocity(s.x).norm() >= kStartSpeed) break;
  }
}

bool TrajectoryTracker::setMode(ReferenceMode mode, double now) {
  TrackingScheme* next = nullptr;
  if (mode == ReferenceMode::kSpatial) next = &spatial_;
  if (mode == ReferenceMode::kTemporal) next = &temporal_;
  if (!next) return false;
  if (next != active_ && loaded_) next->resumeFrom(last_, now);
  active_ = next;
  return true;
}

TrackingOutput TrajectoryTracker::update(double now, const Vec3& position) {
  last_ = active_->update(now, position);
  if (active_ != &spatial_ || !(now - start_time_ < start_window_)) return last_;
  const TrackingOutput clock = temporal_.at(now - start_time_);
  if (clock.time > last_.time) {
    spatial_.resumeFrom(clock, now);
    last_ = clock;
  }
  return last_;
}

}  // namespace sdlqr::trajectory
