#pragma once
// The mission process, bus-free: plays a scenario's events against the simulation clock and
// re-sends the current setpoint command. SIM_CLOCK's utime is the clock; the in-process loop
// drives the same object.
//
//   onClock(clock)   a newer clock plays every event due (COMMAND, DISTURBANCE, PARAMS,
//                    TRAJECTORY through the Outbox, each stamped with the clock and its own
//                    channel's seq) and the due re-send; a clock not after the last is ignored,
//                    one that leaps ahead is taken only once it continues (ClockGate)
//   onWallTime(now)  the clock watchdog: no newer clock for no_clock_timeout_s -> clockLost()
//   onStateEstimate  throw mode only (the scenario's throw_mode): a detected throw publishes ARM,
//                    then GOTO the estimated position (hold there), counted as "throw.detected"
// Trajectories are generated and checked at construction, so a bad request fails before the flight.

#include <cstdint>
#include <optional>
#include <vector>

#include "sdlqr/health/process_health.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"
#include "sdlqr/mission/resender.hpp"
#include "sdlqr/mission/mission_player.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/mission/throw_detector.hpp"
#include "sdlqr/mission/trajectory_request.hpp"
#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::mission {

struct MissionOptions {
  double resend_interval_s = 1.0;   // [s] of simulation time between re-sends of the current command and pull,
                                    // the first a tenth of it after the message (0: never)
  double no_clock_timeout_s = 10.0; // [s] of wall time without a newer clock: clockLost()
};

class MissionCore {
 public:
  // Throws ConfigError naming the event's key when a trajectory cannot be built or its check
  // (against `limits`, trajectory/path_check.hpp) refuses it.
  MissionCore(const Scenario& scenario, const trajectory::TrajectoryParams& trajectory, const PathLimits& limits,
              const MissionOptions& options);

  void onClock(const SimClockTick& clock, Outbox& out);
  void onWallTime(double now_s);
  void onStateEstimate(const StateEstimate& estimate, Outbox& out);
  // Whether the bus main needs STATE_EST at all.
  bool watchesEstimates() const { return throw_detector_.has_value(); }

  // Ports (sdlqr/messages/ports.hpp). STATE_EST in throw mode only: every estimate counts for
  // the detector's acceleration, so a short queue.
  static constexpr auto inputs() {
    return std::tuple{
        ports::Input{&MissionCore::onClock},
        ports::Input{&MissionCore::onStateEstimate, 8}.onlyWhen(&MissionCore::watchesEstimates),
    };
  }
  using Outputs = ports::Publishes<Command, Trajectory, Disturbance, ParamsUpdate>;
  const std::optional<ThrowDetector>& throwDetector() const { return throw_detector_; }

  bool finished() const { return now_utime_ >= 0 && player_.finished(now_utime_); }
  bool clockLost() const { return clock_lost_; }
  int64_t now() const { return now_utime_; }  // -1 before the first clock
  // Called for every event as it is played (the main's log line); nullptr: none.
  using EventObserver = void (*)(const ScenarioEvent& event, int64_t utime);
  void setObserver(EventObserver observer) { observer_ = observer; }
  using ThrowObserver = void (*)(const ThrowDetection& detection);
  void setThrowObserver(ThrowObserver observer) { throw_observer_ = observer; }

  ProcessHealth& health() { return health_; }
  const ProcessHealth& health() const { return health_; }

 private:
  void play(const ScenarioEvent& event, Outbox& out);
  void publishCommand(Command command, int64_t utime, Outbox& out);

  const Scenario& scenario_;
  MissionOptions options_;
  std::vector<Trajectory> trajectories_;  // by event index
  MissionPlayer player_;
  CommandResender resender_;
  DisturbanceResender disturbance_resender_;
  ProcessHealth health_;
  EventObserver observer_ = nullptr;
  ThrowObserver throw_observer_ = nullptr;
  std::optional<ThrowDetector> throw_detector_;
  int64_t throw_armed_utime_ = -1;
  Counters::Id throws_detected_;
  ClockGate clock_gate_;
  int64_t now_utime_ = -1;
  // One sequence per channel: subscribers count gaps in seq as lost messages.
  int64_t command_seq_ = 0, disturbance_seq_ = 0, params_seq_ = 0, trajectory_seq_ = 0;
  int64_t clock_seen_at_wall_ = -1;  // the clock at the last onWallTime
  double clock_wall_s_ = -1.0;       // wall time the clock last advanced
  bool clock_lost_ = false;
};

// One line for the log: "command goto (1.00, 0.00, 1.00) yaw 0.00  [label]".
std::string describeEvent(const ScenarioEvent& event);
// An EventObserver: "sdlqr-mission: t=  1.000 s  <describeEvent>" on stderr.
void logEventToStderr(const ScenarioEvent& event, int64_t utime);
// A ThrowObserver: "sdlqr-mission: t=  3.412 s  throw detected at (...) m, vz ... m/s: arm, hold".
void logThrowToStderr(const ThrowDetection& detection);

}  // namespace sdlqr::mission
