// Setpoint windows (take-off hold, reference jumps: Fig. 5) and pulls (Fig. 4) of a flight.

#include <cmath>
#include <limits>

#include "flight_parts.hpp"

namespace sdlqr::analysis::detail {

namespace {

struct Event {
  double t = 0.0;
  enum Kind { kTakeoff, kGoto, kLand, kPull, kTrajectory } kind = kGoto;
  Vec3 position = Vec3::Zero();
  const Disturbance* disturbance = nullptr;
  const ExpectedEvent* expected = nullptr;
};

// The scenario's events that bound the windows, as the log has them, in time order: take-offs,
// jumps, landings, pulls and trajectories whose message the recorder heard.
std::vector<Event> flightEvents(const logger::FlightLog& log, const std::vector<ExpectedEvent>& expected) {
  std::vector<Event> events;
  for (const ExpectedEvent& x : expected) {
    if (!x.found()) continue;
    Event e;
    e.t = x.seen;
    e.expected = &x;
    const auto i = static_cast<size_t>(x.message);
    switch (x.kind) {
      case ExpectedEvent::Kind::kTakeoff: e.kind = Event::kTakeoff; e.position = log.command[i].position; break;
      case ExpectedEvent::Kind::kGoto: e.kind = Event::kGoto; e.position = log.command[i].position; break;
      case ExpectedEvent::Kind::kLand: e.kind = Event::kLand; break;
      case ExpectedEvent::Kind::kPull: e.kind = Event::kPull; e.disturbance = &log.disturbance[i]; break;
      case ExpectedEvent::Kind::kTrajectory: e.kind = Event::kTrajectory; break;
      default: continue;
    }
    events.push_back(e);
  }
  std::stable_sort(events.begin(), events.end(), [](const Event& a, const Event& b) { return a.t < b.t; });
  return events;
}

// Held reference position shortly before `t` (the controller publishes it every tick).
Vec3 referencePositionBefore(const logger::FlightLog& log, double t) {
  const auto i = log.reference.indexAtOrBefore(static_cast<int64_t>(t * 1e6) - 20000);
  if (i < 0) return Vec3::Constant(kNotReached);
  return position(log.reference[static_cast<size_t>(i)].x);
}

// Where the truth says the vehicle was at `t` (the last sample at or before it, else the first).
Vec3 truthPositionAt(const logger::FlightLog& log, double t) {
  if (log.sim_truth.empty()) return Vec3::Constant(kNotReached);
  const auto i = log.sim_truth.indexAtOrBefore(static_cast<int64_t>(std::llround(t * 1e6)));
  return log.sim_truth[static_cast<size_t>(std::max<std::ptrdiff_t>(i, 0))].position;
}

// Time after `from` at which err stays below `threshold` until `end`; NaN if it ends above.
template <class ErrorOf>
double settleTime(const logger::FlightLog& log, double from, double end, double threshold, ErrorOf error_of) {
  double last_above = -1.0;
  double last_t = from;
  bool any = false;
  forTruthIn(log, from, end, [&](const SimTruth& s) {
    any = true;
    last_t = seconds(s.utime);
    if (error_of(s) >= threshold) last_above = last_t;
  });
  if (!any || last_above >= last_t) return kNotReached;
  return last_above < 0.0 ? 0.0 : last_above - from;
}

SetpointWindow setpointWindow(const logger::FlightLog& log, const Event& e, double end, const Vec3& previous,
                              double settle_error, double hover_window) {
  SetpointWindow w;
  w.label = e.expected->label;
  w.is_jump = e.kind == Event::kGoto;
  w.start = e.t;
  w.end = end;
  if (e.kind == Event::kTakeoff) {
    // Judged against what was commanded (the height above where the vehicle stood), not against
    // the controller's own REFERENCE: a controller that climbs to the wrong height fails.
    w.from = truthPositionAt(log, e.t);
    w.to = w.from + Vec3(0.0, 0.0, e.position[2]);
  } else {
    w.to = e.position;
    w.from = previous.allFinite() ? previous : w.to;
  }
  w.size = (w.to - w.from).norm();
  const Vec3 to = w.to;
  const auto error_of = [&to](const SimTruth& s) { return (s.position - to).norm(); };
  w.settle_time = settleTime(log, w.start, w.end, settle_error, error_of);
  const Vec3 direction = w.size > 1e-9 ? Vec3((w.to - w.from) / w.size) : Vec3::Zero();
  double beyond = 0.0, steady_sum = 0.0, after_settle = 0.0;
  int64_t steady_count = 0;
  const double settled_at = w.start + (std::isfinite(w.settle_time) ? w.settle_time : 1e9);
  forTruthIn(log, w.start, w.end, [&](const SimTruth& s) {
    const double t = seconds(s.utime);
    beyond = std::max(beyond, (s.position - to).dot(direction));
    if (t >= w.end - hover_window) {
      steady_sum += error_of(s);
      ++steady_count;
    }
    if (t >= settled_at) after_settle = std::max(after_settle, error_of(s));
  });
  w.overshoot = w.size > 1e-9 ? beyond / w.size : 0.0;
  if (steady_count > 0) w.steady_error = steady_sum / static_cast<double>(steady_count);
  if (std::isfinite(w.settle_time)) w.max_error_after_settle = after_settle;
  return w;
}

// The pull's return overshoot (PullWindow::return_overshoot), from its setpoint and release.
double returnOvershoot(const logger::FlightLog& log, const PullWindow& p) {
  Vec3 farthest = Vec3::Zero();
  forTruthIn(log, p.start, p.end, [&](const SimTruth& s) {
    if ((s.position - p.setpoint).norm() > farthest.norm()) farthest = s.position - p.setpoint;
  });
  if (farthest.norm() < 1e-9) return 0.0;
  const Vec3 away = farthest.normalized();
  double past = 0.0;
  forTruthIn(log, p.release, p.end, [&](const SimTruth& s) { past = std::max(past, -(s.position - p.setpoint).dot(away)); });
  return past / farthest.norm();
}

PullWindow pullWindow(const logger::FlightLog& log, const Event& e, double end, double return_error) {
  PullWindow p;
  p.label = e.expected->label;
  p.start = e.t;
  p.release = e.t + e.disturbance->duration;
  p.end = end;
  p.disturbance = *e.disturbance;
  p.setpoint = referencePositionBefore(log, e.t + 0.02);
  const Vec3 sp = p.setpoint;
  const auto error_of = [&sp](const SimTruth& s) { return (s.position - sp).norm(); };
  forTruthIn(log, p.start, p.end, [&](const SimTruth& s) { p.max_deviation = std::max(p.max_deviation, error_of(s)); });
  p.return_time = settleTime(log, p.release, p.end, return_error, error_of);
  p.return_overshoot = returnOvershoot(log, p);
  return p;
}


// A window the scenario expected and the log does not hold: every criterion of it fails, naming why.
void addMissingWindows(const std::vector<ExpectedEvent>& expected, FlightReport& report) {
  for (const ExpectedEvent& x : expected) {
    if (x.found()) continue;
    if (x.kind == ExpectedEvent::Kind::kTakeoff || x.kind == ExpectedEvent::Kind::kGoto) {
      SetpointWindow w;
      w.label = x.label;
      w.is_jump = x.kind == ExpectedEvent::Kind::kGoto;
      w.start = w.end = x.at;
      w.missing = x.describe();
      report.setpoints.push_back(w);
    } else if (x.kind == ExpectedEvent::Kind::kPull && !x.on_trajectory) {
      PullWindow p;
      p.label = x.label;
      p.start = p.release = p.end = x.at;
      p.missing = x.describe();
      report.pulls.push_back(p);
    }
  }
  const auto by_start = [](const auto& a, const auto& b) { return a.start < b.start; };
  std::stable_sort(report.setpoints.begin(), report.setpoints.end(), by_start);
  std::stable_sort(report.pulls.begin(), report.pulls.end(), by_start);
}

}  // namespace

void analyzeWindows(const logger::FlightLog& log, const AnalysisOptions& options, FlightReport& report,
                    const mission::Scenario& scenario) {
  const double log_end = log.sim_truth.empty() ? 0.0 : seconds(log.sim_truth.back().utime);
  const std::vector<Event> events = flightEvents(log, report.events);
  const double settle_error = scenario.criterion("jump_settle_error", options.settle_error);
  const double return_error = scenario.criterion("pull_return_error", options.return_error);
  report.settle_error = settle_error;
  report.return_error = return_error;
  Vec3 previous_setpoint = Vec3::Constant(kNotReached);
  for (size_t i = 0; i < events.size(); ++i) {
    const Event& e = events[i];
    if (e.kind == Event::kTrajectory) previous_setpoint = Vec3::Constant(kNotReached);
    const double end = i + 1 < events.size() ? events[i + 1].t : log_end;
    if (e.kind == Event::kTakeoff || e.kind == Event::kGoto) {
      report.setpoints.push_back(setpointWindow(log, e, end, previous_setpoint, settle_error, options.hover_window));
      previous_setpoint = report.setpoints.back().to;
    } else if (e.kind == Event::kPull && !e.expected->on_trajectory) {
      // Pulls the scenario plays on a trajectory are judged against the path (path_tracking.hpp).
      report.pulls.push_back(pullWindow(log, e, end, return_error));
    }
  }
  addMissingWindows(report.events, report);
}

void analyzeLandings(const logger::FlightLog& log, FlightReport& report) {
  for (const ExpectedEvent& x : report.events) {
    if (x.kind != ExpectedEvent::Kind::kLand) continue;
    Landing landing;
    landing.label = x.label;
    landing.start = x.found() ? x.seen : x.at;
    if (!x.found()) landing.missing = x.describe();
    bool airborne = false;
    double vz = 0.0;
    forTruthIn(log, landing.start, std::numeric_limits<double>::infinity(), [&](const SimTruth& s) {
      if (std::isfinite(landing.touchdown)) return;
      if (s.on_ground && airborne) {
        landing.touchdown = seconds(s.utime);
        landing.touchdown_speed = std::abs(vz);
      }
      airborne = !s.on_ground;
      vz = s.velocity[2];
    });
    report.landings.push_back(landing);
  }
}

}  // namespace sdlqr::analysis::detail
