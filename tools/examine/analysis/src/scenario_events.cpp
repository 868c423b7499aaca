#include "sdlqr/analysis/scenario_events.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "flight_parts.hpp"
#include "sdlqr/messages/channels.hpp"

namespace sdlqr::analysis {

namespace {

using Kind = ExpectedEvent::Kind;

constexpr double kEarly = 1e-6;  // [s] a message stamped by the first clock at the event's time

using detail::seconds;

double startOf(int64_t start_utime, int64_t utime) { return seconds(start_utime > 0 ? start_utime : utime); }

bool same(double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(a)); }
bool same(const Vec3& a, const Vec3& b) { return same(a[0], b[0]) && same(a[1], b[1]) && same(a[2], b[2]); }

const char* defaultLabel(Kind kind) {
  switch (kind) {
    case Kind::kArm: return "arm";
    case Kind::kDisarm: return "disarm";
    case Kind::kTakeoff: return "takeoff";
    case Kind::kGoto: return "goto";
    case Kind::kLand: return "land";
    case Kind::kPull: return "pull";
    case Kind::kParams: return "params";
    case Kind::kTrajectory: return "trajectory";
    case Kind::kThrow: return "throw";
  }
  return "event";
}

ExpectedEvent fromScenario(const mission::ScenarioEvent& s) {
  ExpectedEvent e;
  e.at = s.at;
  e.source = &s;
  e.label = s.label;
  switch (s.kind) {
    case mission::ScenarioEvent::Kind::kCommand:
      e.channel = channel::kCommand;
      switch (s.command.command) {
        case CommandType::kArm: e.kind = Kind::kArm; break;
        case CommandType::kDisarm: e.kind = Kind::kDisarm; break;
        case CommandType::kTakeoff: e.kind = Kind::kTakeoff; break;
        case CommandType::kGoto: e.kind = Kind::kGoto; break;
        case CommandType::kLand: e.kind = Kind::kLand; break;
      }
      break;
    case mission::ScenarioEvent::Kind::kDisturbance:
      e.kind = Kind::kPull;
      e.channel = channel::kDisturbance;
      break;
    case mission::ScenarioEvent::Kind::kParams:
      e.kind = Kind::kParams;
      e.channel = channel::kParams;
      break;
    case mission::ScenarioEvent::Kind::kTrajectory:
      e.kind = Kind::kTrajectory;
      e.channel = channel::kTrajectory;
      break;
  }
  return e;
}

// Unlabelled trajectories are numbered ("trajectory 2"); any other label seen twice gets its time.
void makeLabelsUnique(std::vector<ExpectedEvent>& events) {
  int trajectories = 0;
  std::map<std::string, int> uses;
  for (ExpectedEvent& e : events) {
    if (e.kind == Kind::kTrajectory && e.label.empty()) e.label = "trajectory " + std::to_string(++trajectories);
    if (e.label.empty()) e.label = defaultLabel(e.kind);
    ++uses[e.label];
  }
  for (ExpectedEvent& e : events) {
    if (uses[e.label] < 2) continue;
    char at[32];
    std::snprintf(at, sizeof at, " at %.1f s", e.at);
    e.label += at;
  }
}

// A pull played after a trajectory, with no setpoint command between, happens on the path.
void markPullsOnTrajectories(std::vector<ExpectedEvent>& events) {
  bool tracking = false;
  for (ExpectedEvent& e : events) {
    if (e.kind == Kind::kTrajectory) tracking = true;
    if (e.kind == Kind::kTakeoff || e.kind == Kind::kGoto || e.kind == Kind::kLand) tracking = false;
    if (e.kind == Kind::kPull) e.on_trajectory = tracking;
  }
}

bool matches(const ExpectedEvent& e, const Command& c) {
  if (e.kind == Kind::kThrow) return c.command == CommandType::kArm;
  const Command& want = e.source->command;
  if (c.command != want.command) return false;
  if (want.command == CommandType::kTakeoff) return same(c.position[2], want.position[2]);
  if (want.command == CommandType::kGoto) return same(c.position, want.position) && same(c.yaw, want.yaw);
  return true;
}

bool matches(const ExpectedEvent& e, const Disturbance& d) {
  const Disturbance& want = e.source->disturbance;
  return d.mode == want.mode && same(d.duration, want.duration);
}

bool matches(const ExpectedEvent& e, const ParamsUpdate& p) { return p.field_mask == e.source->params.field_mask; }

bool matches(const ExpectedEvent& e, const Trajectory& t) { return t.tracking == e.source->trajectory.tracking; }

double timeOf(const Command& c) { return seconds(c.utime); }
double timeOf(const Disturbance& d) { return startOf(d.start_utime, d.utime); }
double timeOf(const ParamsUpdate& p) { return seconds(p.utime); }
double timeOf(const Trajectory& t) { return startOf(t.start_utime, t.utime); }

// The first unclaimed message (by seq: a re-sent command is the same message) in [at, until).
template <class T>
void find(ExpectedEvent& e, double until, const logger::Series<T>& series, std::set<int64_t>& claimed) {
  for (size_t i = 0; i < series.size(); ++i) {
    const T& m = series[i];
    const double t = timeOf(m);
    if (t < e.at - kEarly || t >= until || claimed.count(m.seq) || !matches(e, m)) continue;
    claimed.insert(m.seq);
    e.seen = t;
    e.message = static_cast<std::ptrdiff_t>(i);
    return;
  }
}

}  // namespace

std::string ExpectedEvent::describe() const {
  char text[256];
  const char* what = kind == Kind::kThrow ? "the throw detector's ARM" : channel.c_str();
  if (found()) {
    std::snprintf(text, sizeof text, "%s at %.1f s: %s in the log at %.2f s", label.c_str(), at, what, seen);
  } else {
    std::snprintf(text, sizeof text, "%s at %.1f s: %s not in the log", label.c_str(), at, what);
  }
  return text;
}

std::vector<ExpectedEvent> expectedEvents(const mission::Scenario& scenario) {
  std::vector<ExpectedEvent> events;
  for (const mission::ScenarioEvent& s : scenario.events) events.push_back(fromScenario(s));
  if (scenario.sim.throw_event.enabled()) {
    ExpectedEvent e;
    e.kind = Kind::kThrow;
    e.channel = channel::kCommand;
    e.at = scenario.sim.throw_event.releaseTime();
    events.push_back(e);
  }
  std::stable_sort(events.begin(), events.end(), [](const ExpectedEvent& a, const ExpectedEvent& b) { return a.at < b.at; });
  makeLabelsUnique(events);
  markPullsOnTrajectories(events);
  return events;
}

void findInLog(std::vector<ExpectedEvent>& events, const logger::FlightLog& log) {
  std::map<std::string, std::set<int64_t>> claimed;  // per channel
  for (size_t i = 0; i < events.size(); ++i) {
    ExpectedEvent& e = events[i];
    // Until the next event on the same channel is due: its message is that event's.
    double until = std::numeric_limits<double>::infinity();
    for (size_t j = i + 1; j < events.size(); ++j) {
      if (events[j].channel == e.channel && events[j].at > e.at + kEarly) {
        until = events[j].at;
        break;
      }
    }
    std::set<int64_t>& taken = claimed[e.channel];
    if (e.channel == channel::kCommand) find(e, until, log.command, taken);
    else if (e.channel == channel::kDisturbance) find(e, until, log.disturbance, taken);
    else if (e.channel == channel::kParams) find(e, until, log.params, taken);
    else if (e.channel == channel::kTrajectory) find(e, until, log.trajectory, taken);
  }
}

}  // namespace sdlqr::analysis
