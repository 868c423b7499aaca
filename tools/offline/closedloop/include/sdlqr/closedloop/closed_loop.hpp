#pragma once
// The in-process closed loop: the very process cores the flight executables bind to the bus —
// simulator, estimator, gain solver, controller, lowlevel, mission — stepped together without a
// bus, so every message passes the same validation, gates and counters as on the bus. Each
// message reaches its consumers within the physics step that produced it, in the order the
// processes would see it (the bodyrate loop acts on an IMU sample before the command computed
// from the same sample arrives). Wall time is simulation time here: each core's onWallTime()
// gets the simulation time [s] before every physics step. Deterministic: the same scenario and
// seed give the same flight, bit for bit, much faster than real time — for scenario regression
// and Monte Carlo.
//
// The routing is the cores' declared ports (sdlqr/messages/ports.hpp, in_process_wiring.hpp).
// Every message is recorded into a FlightLog, so the analysis of a bus flight applies unchanged.
// inject() puts a message on the loop as if a foreign publisher had sent it (hostile-input tests).

#include <string>

#include "sdlqr/controller/controller_core.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/estimator/estimator_core.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/gains/gains_core.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/lowlevel/lowlevel_core.hpp"
#include "sdlqr/lowlevel/lowlevel_params.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/messages/in_process_wiring.hpp"
#include "sdlqr/mission/mission_core.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/sim/sim_core.hpp"
#include "sdlqr/params/vehicle_file.hpp"
#include "sdlqr/sim/sim_params.hpp"
#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::closedloop {

// Every section of a vehicle file, as the processes read them (StackConfig::load throws
// ConfigError naming the key).
using StackConfig = params::VehicleFile;

// Every channel is recorded but these: IMU and MOTOR_CMD (1 kHz: large) unless asked for;
// SIM_CLOCK never (the scenario player's clock: no analysis reads it).
struct RecordOptions {
  bool imu = false;
  bool motor_command = false;
};

// What the simulator flies, when it differs from the vehicle the stack believes it flies (the
// lowlevel's mixer and hover model keep config.vehicle): a Monte Carlo batch's perturbed plant.
struct Plant {
  VehicleParams vehicle;
  sim::SimParams sim;
};

// The mission's re-sends are off by default (0): the loop has no restarted process to tell.
// `plant`: the simulator's airframe when it differs from the one the stack assumes (a plant
// mismatch: the bodyrate loop and the controller keep config.vehicle); nullptr: config.vehicle.
class ClosedLoop {
 public:
  ClosedLoop(const StackConfig& config, const mission::Scenario& scenario, RecordOptions record = {},
             double command_resend_s = 0.0);
  // The simulator flies `plant`; every other core reads `config` (the nominal model).
  ClosedLoop(const StackConfig& config, const Plant& plant, const mission::Scenario& scenario,
             RecordOptions record = {}, double command_resend_s = 0.0);
  ClosedLoop(const ClosedLoop&) = delete;
  ClosedLoop& operator=(const ClosedLoop&) = delete;

  // One physics step. Returns false once the scenario's duration has passed.
  bool step();
  void run();
  // Delivers a message to its consumers now (recorded like every other), as a foreign publisher.
  template <class Msg>
  void inject(const Msg& message) {
    wiring_.publish(message);
  }

  int64_t utime() const { return sim_.simulator().utime(); }
  const logger::FlightLog& log() const { return recorder_.log; }
  // Records into `storage`'s memory (emptied first), before the first step: a caller flying
  // flight after flight hands back the last flight's log and the next one allocates nothing.
  void recordInto(logger::FlightLog&& storage);
  // The recorded flight, moved out: the loop's own log is left empty.
  logger::FlightLog takeLog();
  const sim::SimCore& sim() const { return sim_; }
  const estimator::EstimatorCore& estimator() const { return estimator_; }
  const gains::GainsCore& gains() const { return gains_; }
  const controller::ControllerCore& controller() const { return controller_; }
  const lowlevel::LowlevelCore& lowlevel() const { return lowlevel_; }
  const mission::MissionCore& mission() const { return mission_; }

 private:
  // Every message into its series of the log, as the recorder would on the bus.
  struct Recorder {
    RecordOptions options;
    logger::FlightLog log;
    template <class Msg>
    void operator()(const Msg& m) {
      if constexpr (std::is_same_v<Msg, ImuSample>) {
        if (!options.imu) return;
      } else if constexpr (std::is_same_v<Msg, MotorCommand>) {
        if (!options.motor_command) return;
      }
      if constexpr (logger::kFlightLogRecords<Msg> && !std::is_same_v<Msg, SimClockTick>) {
        logger::Series<Msg>& series = log.series<Msg>();
        series.messages.push_back(m);
        series.receive_utime.push_back(m.utime);
      }
    }
  };

  // Room for the whole flight in the 1 kHz and 250 Hz series, so recording never reallocates.
  void reserveRecording();

  Recorder recorder_;
  double duration_s_;
  int truth_rate_hz_;
  int imu_rate_hz_;
  int64_t estimate_period_us_;
  sim::SimCore sim_;
  estimator::EstimatorCore estimator_;
  lowlevel::LowlevelCore lowlevel_;
  controller::ControllerCore controller_;
  gains::GainsCore gains_;
  mission::MissionCore mission_;
  // The order a message reaches its consumers in: the bodyrate loop acts on an IMU sample before
  // the estimator publishes from it (the command computed from that sample comes a step later,
  // as on the bus); the solver gets an estimate before the controller, so its GAINS reach the
  // controller before the tick of that estimate; the mission (throw mode) after the controller,
  // so a throw's ARM and GOTO follow that tick.
  InProcessWiring<Recorder, lowlevel::LowlevelCore, estimator::EstimatorCore, gains::GainsCore,
                  controller::ControllerCore, mission::MissionCore, sim::SimCore>
      wiring_{recorder_, lowlevel_, estimator_, gains_, controller_, mission_, sim_};
};

}  // namespace sdlqr::closedloop
