#include "sdlqr/mission/mission_core.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "sdlqr/mission/trajectory_request.hpp"

namespace sdlqr::mission {

namespace {

// Each trajectory event's path, checked from the hover the scenario leaves the vehicle in before it:
// the last take-off height or GOTO (the take-off from the origin of the world), else the end of the
// path flown before, else the path's own start.
std::vector<Trajectory> buildTrajectories(const Scenario& scenario, const trajectory::TrajectoryParams& params,
                                          const PathLimits& limits) {
  std::vector<Trajectory> trajectories(scenario.events.size());
  bool known = false;
  Vec3 hover = Vec3::Zero();
  double yaw = 0.0;
  for (size_t i = 0; i < scenario.events.size(); ++i) {
    const ScenarioEvent& event = scenario.events[i];
    if (event.kind == ScenarioEvent::Kind::kCommand && event.command.command == CommandType::kTakeoff) {
      hover = Vec3(0.0, 0.0, event.command.position[2]);
      known = true;
    } else if (event.kind == ScenarioEvent::Kind::kCommand && event.command.command == CommandType::kGoto) {
      hover = event.command.position;
      yaw = event.command.yaw;
      known = true;
    }
    if (event.kind != ScenarioEvent::Kind::kTrajectory) continue;
    const std::string key = "events[" + std::to_string(i) + "].trajectory";
    if (!known) {
      // Expected at the path's start: built once to learn where that is.
      const Trajectory probe = buildTrajectory(event.trajectory, params, limits, Vec3::Zero(), yaw, key + "(probe)");
      hover = position(probe.samples.front().x);
    }
    trajectories[i] = buildTrajectory(event.trajectory, params, limits, hover, yaw, key);
    hover = position(trajectories[i].samples.back().x);
    known = true;
  }
  return trajectories;
}

}  // namespace

MissionCore::MissionCore(const Scenario& scenario, const trajectory::TrajectoryParams& trajectory,
                         const PathLimits& limits, const MissionOptions& options)
    : scenario_(scenario),
      options_(options),
      trajectories_(buildTrajectories(scenario, trajectory, limits)),
      player_(scenario),
      resender_(static_cast<int64_t>(options.resend_interval_s * 1e6)),
      disturbance_resender_(static_cast<int64_t>(options.resend_interval_s * 1e6)),
      throws_detected_(health_.counters().add("throw.detected")) {
  if (scenario.throw_mode.enabled()) {
    throw_detector_.emplace(scenario.throw_mode, limits.lqr.gravity);
    throw_armed_utime_ = static_cast<int64_t>(scenario.throw_mode.at * 1e6);
  }
}

void MissionCore::publishCommand(Command command, int64_t utime, Outbox& out) {
  command.utime = utime;
  command.seq = command_seq_++;
  out.publish(command);
  resender_.sent(command);
}

void MissionCore::onStateEstimate(const StateEstimate& estimate, Outbox& out) {
  if (!throw_detector_ || estimate.utime < throw_armed_utime_) return;
  const std::optional<ThrowDetection> detection = throw_detector_->onEstimate(estimate);
  if (!detection) return;
  health_.counters().increment(throws_detected_);
  // Stamped with the estimate's time: every consumer has that estimate (or a later one) by now.
  const int64_t utime = std::max(now_utime_, detection->utime);
  Command arm;
  arm.command = CommandType::kArm;
  publishCommand(arm, utime, out);
  Command hold;
  hold.command = CommandType::kGoto;
  hold.position = detection->position;
  hold.yaw = detection->yaw;
  publishCommand(hold, utime, out);
  if (throw_observer_) throw_observer_(*detection);
}

void MissionCore::onClock(const SimClockTick& clock, Outbox& out) {
  const int64_t utime = clock.utime;
  // A clock that leaps (a forged or corrupt SIM_CLOCK: faults_fuzz_flight once saw the mission jump
  // to 2.7e10 s and play its landing at once) is taken only once it continues, as the controller's
  // and the gain solver's STATE_EST clock (ClockGate); a clock not after the last is ignored.
  if (health_.reject(Stream::kSimClock, clock_gate_.offer(utime))) return;
  now_utime_ = utime;
  health_.setSimTime(utime);
  while (const ScenarioEvent* event = player_.nextDue(utime)) {
    if (observer_) observer_(*event, utime);
    play(*event, out);
  }
  if (const Command* resend = resender_.due(utime)) out.publish(*resend);
  if (const Disturbance* resend = disturbance_resender_.due(utime)) out.publish(*resend);
}

void MissionCore::play(const ScenarioEvent& event, Outbox& out) {
  switch (event.kind) {
    case ScenarioEvent::Kind::kCommand:
      publishCommand(event.command, now_utime_, out);
      break;
    case ScenarioEvent::Kind::kDisturbance: {
      Disturbance disturbance = event.disturbance;
      disturbance.utime = now_utime_;
      disturbance.start_utime = now_utime_;
      disturbance.seq = disturbance_seq_++;
      out.publish(disturbance);
      disturbance_resender_.sent(disturbance);
      break;
    }
    case ScenarioEvent::Kind::kParams: {
      ParamsUpdate params = event.params;
      params.utime = now_utime_;
      params.seq = params_seq_++;
      out.publish(params);
      break;
    }
    case ScenarioEvent::Kind::kTrajectory: {
      Trajectory trajectory = trajectories_[static_cast<size_t>(&event - scenario_.events.data())];
      trajectory.utime = now_utime_;
      trajectory.start_utime = now_utime_;
      trajectory.seq = trajectory_seq_++;
      out.publish(trajectory);
      break;
    }
  }
}

void MissionCore::onWallTime(double now_s) {
  if (clock_wall_s_ < 0.0 || now_utime_ != clock_seen_at_wall_) {
    if (now_utime_ != clock_seen_at_wall_) health_.setState(ProcessState::kRunning);
    clock_seen_at_wall_ = now_utime_;
    clock_wall_s_ = now_s;
    return;
  }
  if (now_s - clock_wall_s_ > options_.no_clock_timeout_s) clock_lost_ = true;
}

std::string describeEvent(const ScenarioEvent& event) {
  char text[256];
  switch (event.kind) {
    case ScenarioEvent::Kind::kCommand: {
      static const char* names[] = {"?", "arm", "disarm", "takeoff", "goto", "land"};
      const int index = static_cast<int>(event.command.command);
      std::snprintf(text, sizeof text, "command %s (%.2f, %.2f, %.2f) yaw %.2f",
                    names[index >= 1 && index <= 5 ? index : 0], event.command.position[0], event.command.position[1],
                    event.command.position[2], event.command.yaw);
      break;
    }
    case ScenarioEvent::Kind::kDisturbance:
      if (event.disturbance.mode == DisturbanceMode::kHold) {
        std::snprintf(text, sizeof text, "disturbance hold at (%.2f, %.2f, %.2f) m, %.0f N/m, for %.2f s",
                      event.disturbance.hold_position[0], event.disturbance.hold_position[1],
                      event.disturbance.hold_position[2], event.disturbance.hold_stiffness, event.disturbance.duration);
      } else {
        std::snprintf(text, sizeof text, "disturbance force (%.2f, %.2f, %.2f) N for %.2f s", event.disturbance.force[0],
                      event.disturbance.force[1], event.disturbance.force[2], event.disturbance.duration);
      }
      break;
    case ScenarioEvent::Kind::kParams:
      std::snprintf(text, sizeof text, "params mask %d", event.params.field_mask);
      break;
    case ScenarioEvent::Kind::kTrajectory:
      std::snprintf(text, sizeof text, "trajectory %s x%d (%s tracking)", event.trajectory.generator.c_str(),
                    event.trajectory.laps,
                    event.trajectory.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial");
      break;
  }
  std::string line = text;
  if (!event.label.empty()) line += "  [" + event.label + "]";
  return line;
}

void logEventToStderr(const ScenarioEvent& event, int64_t utime) {
  std::fprintf(stderr, "sdlqr-mission: t=%7.3f s  %s\n", 1e-6 * static_cast<double>(utime), describeEvent(event).c_str());
}

void logThrowToStderr(const ThrowDetection& d) {
  std::fprintf(stderr, "sdlqr-mission: t=%7.3f s  throw detected at (%.2f, %.2f, %.2f) m, vz %.2f m/s: arm, hold there\n",
               1e-6 * static_cast<double>(d.utime), d.position[0], d.position[1], d.position[2], d.velocity[2]);
}

}  // namespace sdlqr::mission
