#pragma once
// The in-process closed loop: the same libraries the flight processes run — plant,
// estimator, gain solver, controller, bodyrate loop, scenario player — stepped together without a
// bus. Each message reaches its consumers within the physics step that produced it, in the order
// the processes would see it (the bodyrate loop acts on an IMU sample before the command computed
// from the same sample arrives). Deterministic: the same scenario and seed give the same flight,
// bit for bit, much faster than real time — for scenario regression and Monte Carlo.
//
// Every message is recorded into a FlightLog, so the analysis of a bus flight applies unchanged.

#include <memory>
#include <string>

#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/math/vehicle.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/gains/gain_scheduler.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/controller/state_dependent_lqr.hpp"
#include "sdlqr/estimator/estimator.hpp"
#include "sdlqr/estimator/estimator_params.hpp"
#include "sdlqr/logger/flight_log.hpp"
#include "sdlqr/lowlevel/bodyrate_loop.hpp"
#include "sdlqr/lowlevel/lowlevel_params.hpp"
#include "sdlqr/mission/mission_player.hpp"
#include "sdlqr/mission/scenario.hpp"
#include "sdlqr/params/vehicle_file.hpp"
#include "sdlqr/sim/sim_params.hpp"
#include "sdlqr/sim/simulator.hpp"
#include "sdlqr/trajectory/params.hpp"

namespace sdlqr::closedloop {

// Every section of a vehicle file, as the processes read them (StackConfig::load throws
// ConfigError naming the key).
using StackConfig = params::VehicleFile;

struct RecordOptions {
  bool imu = false;         // 1 kHz: large; off unless asked for
  bool motor_command = false;
};

class ClosedLoop {
 public:
  ClosedLoop(const StackConfig& config, const mission::Scenario& scenario, RecordOptions record = {});

  // One physics step. Returns false once the scenario's duration has passed.
  bool step();
  void run();

  int64_t utime() const { return sim_.utime(); }
  const logger::FlightLog& log() const { return log_; }
  const sim::Simulator& simulator() const { return sim_; }
  const estimator::Estimator& estimator() const { return estimator_; }
  const controller::StateDependentLqr& controller() const { return controller_; }
  const lowlevel::BodyrateLoop& lowlevel() const { return lowlevel_; }

 private:
  void play(const mission::ScenarioEvent& event, size_t index);
  template <class T>
  static void record(logger::Series<T>& series, const T& message) {
    series.messages.push_back(message);
    series.receive_utime.push_back(message.utime);
  }

  StackConfig config_;
  const mission::Scenario& scenario_;
  RecordOptions record_;
  sim::Simulator sim_;
  estimator::Estimator estimator_;
  lowlevel::BodyrateLoop lowlevel_;
  controller::StateDependentLqr controller_;
  gains::GainScheduler gains_;
  mission::MissionPlayer player_;
  std::vector<Trajectory> trajectories_;
  controller::StateDependentLqr::Tick tick_;
  int64_t command_seq_ = 0;
  int64_t disturbance_seq_ = 0;
  int64_t params_seq_ = 0;
  int64_t trajectory_seq_ = 0;
  logger::FlightLog log_;
};

}  // namespace sdlqr::closedloop
