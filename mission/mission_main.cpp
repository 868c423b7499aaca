// sdlqr-mission: plays a scenario file's events on the bus against simulation time.

#include <chrono>
#include <cstdio>
#include <iostream>

#include "sdlqr/config/cli.hpp"
#include "sdlqr/config/print_config.hpp"
#include "sdlqr/mission/command_resender.hpp"
#include "sdlqr/mission/mission_player.hpp"
#include "sdlqr/mission/trajectory_request.hpp"
#include "sdlqr/bus/convert.hpp"
#include "sdlqr/bus/node.hpp"

using namespace sdlqr;

namespace {

void describe(const mission::ScenarioEvent& event, double now) {
  std::fprintf(stderr, "sdlqr-mission: t=%7.3f s  ", now);
  switch (event.kind) {
    case mission::ScenarioEvent::Kind::kCommand: {
      static const char* names[] = {"?", "arm", "disarm", "takeoff", "goto", "land"};
      const int index = static_cast<int>(event.command.command);
      std::fprintf(stderr, "command %s (%.2f, %.2f, %.2f) yaw %.2f", names[index >= 1 && index <= 5 ? index : 0],
                   event.command.position[0], event.command.position[1], event.command.position[2], event.command.yaw);
      break;
    }
    case mission::ScenarioEvent::Kind::kDisturbance:
      if (event.disturbance.mode == DisturbanceMode::kHold) {
        std::fprintf(stderr, "disturbance hold at (%.2f, %.2f, %.2f) m, %.0f N/m, for %.2f s",
                     event.disturbance.hold_position[0], event.disturbance.hold_position[1],
                     event.disturbance.hold_position[2], event.disturbance.hold_stiffness, event.disturbance.duration);
      } else {
        std::fprintf(stderr, "disturbance force (%.2f, %.2f, %.2f) N for %.2f s", event.disturbance.force[0],
                     event.disturbance.force[1], event.disturbance.force[2], event.disturbance.duration);
      }
      break;
    case mission::ScenarioEvent::Kind::kParams:
      std::fprintf(stderr, "params mask %d", event.params.field_mask);
      break;
    case mission::ScenarioEvent::Kind::kTrajectory:
      std::fprintf(stderr, "trajectory %s x%d (%s tracking)", event.trajectory.generator.c_str(), event.trajectory.laps,
                   event.trajectory.tracking == ReferenceMode::kTemporal ? "temporal" : "spatial");
      break;
  }
  if (!event.label.empty()) std::fprintf(stderr, "  [%s]", event.label.c_str());
  std::fprintf(stderr, "\n");
}

}  // namespace

int main(int argc, char** argv) {
  return runMain("sdlqr-mission", [&] {
    ProcessOptions options;
    double no_clock_timeout = 10.0;
    bool describe_only = false;
    std::vector<std::string> positional;
    ArgParser parser("sdlqr-mission",
                     "Scenario player: publishes COMMAND, TRAJECTORY, DISTURBANCE and PARAMS at the times of a\n"
                     "scenario file, using the IMU's utime as the clock. Exits 0 when the scenario's duration\n"
                     "of simulation time has passed.");
    addProcessOptions(parser, &options);
    parser.addOption("--no-clock-timeout", &no_clock_timeout, "S",
                     "give up (exit 1) when no IMU arrives for this many wall seconds (default 10)");
    double resend_interval = 1.0;
    parser.addOption("--resend-interval", &resend_interval, "S",
                     "re-send the current TAKEOFF/GOTO every S s of simulation time, for a restarted\n"
                     "controller (default 1, 0: never)");
    parser.addFlag("--describe", &describe_only,
                   "validate the scenario, print name, vehicle, seed, rate and duration as key=value lines, exit");
    parser.allowPositional(&positional, "SCENARIO.yaml");
    parser.parseOrExit(argc, argv);
    if (positional.size() != 1) throw std::invalid_argument("expected one scenario file (see --help)");
    if (!(resend_interval >= 0.0 && resend_interval <= 60.0)) {
      throw std::invalid_argument("--resend-interval: must be in [0, 60] s");
    }

    const mission::Scenario scenario = mission::Scenario::load(positional[0]);
    const ConfigReader vehicle_config = loadVehicleConfig(
        options.config_path.empty() ? scenario.vehicle_path : options.config_path);
    const LqrParams lqr = LqrParams::load(vehicle_config.child("lqr"));
    const trajectory::TrajectoryParams trajectory_params =
        trajectory::TrajectoryParams::load(vehicle_config.child("trajectory"));
    if (options.print_config) {
      printProcessConfig(std::cout, "sdlqr-mission", options.config_path.empty() ? scenario.vehicle_path : options.config_path,
                         {printedSection("lqr", lqr), printedSection("trajectory", trajectory_params)});
      return 0;
    }
    // Trajectories are generated before the flight so a bad request fails here, not mid-air.
    std::vector<Trajectory> trajectories(scenario.events.size());
    for (size_t i = 0; i < scenario.events.size(); ++i) {
      if (scenario.events[i].kind == mission::ScenarioEvent::Kind::kTrajectory) {
        trajectories[i] = mission::buildTrajectory(scenario.events[i].trajectory, trajectory_params, lqr,
                                                   "events[" + std::to_string(i) + "].trajectory");
      }
    }

    if (describe_only) {
      std::printf("name=%s\nvehicle=%s\nseed=%lld\nrate=%.17g\nduration=%.17g\nevents=%zu\n", scenario.name.c_str(),
                  (options.config_path.empty() ? scenario.vehicle_path : options.config_path).c_str(), scenario.seed,
                  scenario.rate, scenario.duration, scenario.events.size());
      return 0;
    }

    bus::Node bus("sdlqr-mission", options);
    mission::MissionPlayer player(scenario);
    mission::CommandResender resender(static_cast<int64_t>(resend_interval * 1e6));
    int64_t now_utime = -1;
    // One sequence per channel: subscribers count gaps in seq as lost messages.
    int64_t command_seq = 0, disturbance_seq = 0, params_seq = 0, trajectory_seq = 0;
    bool finished = false;
    bus.subscribe<imu_t>(channel::kImu, [&](const imu_t& imu) {
      if (imu.utime <= now_utime) return;
      now_utime = imu.utime;
      bus.setSimTime(now_utime);
    });

    std::fprintf(stderr, "sdlqr-mission: scenario '%s', %zu events, %.1f s\n", scenario.name.c_str(),
                 scenario.events.size(), scenario.duration);
    auto last_clock = std::chrono::steady_clock::now();
    int64_t last_seen_utime = -1;
    bus.setState(bus::ProcessState::kStarting);
    while (bus.spin(20)) {
      const auto wall_now = std::chrono::steady_clock::now();
      if (now_utime != last_seen_utime) {
        last_seen_utime = now_utime;
        last_clock = wall_now;
        bus.setState(bus::ProcessState::kRunning);
      } else if (std::chrono::duration<double>(wall_now - last_clock).count() > no_clock_timeout) {
        std::fprintf(stderr, "sdlqr-mission: no IMU for %.0f s: is sdlqr-sim running on this bus?\n",
                     no_clock_timeout);
        bus.shutdown();
        return 1;
      }
      if (now_utime < 0) continue;
      while (const mission::ScenarioEvent* event = player.nextDue(now_utime)) {
        const size_t index = static_cast<size_t>(event - scenario.events.data());
        describe(*event, static_cast<double>(now_utime) * 1e-6);
        switch (event->kind) {
          case mission::ScenarioEvent::Kind::kCommand: {
            Command command = event->command;
            command.utime = now_utime;
            command.seq = command_seq++;
            bus.publish(channel::kCommand, bus::toLcm(command));
            resender.sent(command);
            break;
          }
          case mission::ScenarioEvent::Kind::kDisturbance: {
            Disturbance disturbance = event->disturbance;
            disturbance.utime = now_utime;
            disturbance.start_utime = now_utime;
            disturbance.seq = disturbance_seq++;
            bus.publish(channel::kDisturbance, bus::toLcm(disturbance));
            break;
          }
          case mission::ScenarioEvent::Kind::kParams: {
            ParamsUpdate params = event->params;
            params.utime = now_utime;
            params.seq = params_seq++;
            bus.publish(channel::kParams, bus::toLcm(params));
            break;
          }
          case mission::ScenarioEvent::Kind::kTrajectory: {
            Trajectory trajectory = trajectories[index];
            trajectory.utime = now_utime;
            trajectory.start_utime = now_utime;
            trajectory.seq = trajectory_seq++;
            bus.publish(channel::kTrajectory, bus::toLcm(trajectory));
            break;
          }
        }
      }
      if (const Command* resend = resender.due(now_utime)) bus.publish(channel::kCommand, bus::toLcm(*resend));
      if (player.finished(now_utime)) {
        finished = true;
        break;
      }
    }
    std::fprintf(stderr, "sdlqr-mission: %s at t=%.3f s\n", finished ? "scenario complete" : "stopped",
                 static_cast<double>(now_utime) * 1e-6);
    bus.shutdown();
    return 0;
  });
}
