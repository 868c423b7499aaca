#pragma once
// Recomputes a recorded flight: fresh process cores of sdlqr-estimator, sdlqr-gains and
// sdlqr-controller (the very objects those executables bind to the bus, with every validation,
// gate and counter) are fed the recorded inputs in one thread, so the result does not depend on
// scheduling, and an input the bus refused is refused here the same way, counted in the same
// health (the cores' onWallTime() gets the simulation time of each input, in seconds).
//
// The pairing contract. On the bus, which message a process handles first is a race (a GAINS
// may land just before or just after a controller tick). Every output therefore names the inputs
// it used, and the replay feeds each process the same pairing:
//   - estimator: IMU and VIO_POSE in the recorder's order; STATE_EST names imu_seq and vio_seq.
//   - controller: each recomputed STATE_EST is handed over where the recorded STATE_EST of that
//     seq sits in the log (TRAJECTORY, PARAMS in between keep their place); before the tick of a
//     recorded RATE_CMD, the controller is given the GAINS that RATE_CMD names (gains_seq),
//     recomputed by the replay's solver, and every COMMAND up to the one its REFERENCE names
//     (command_seq), even one the recorder heard later; a COMMAND the recorder heard before an
//     estimate whose tick names an older one is held back until after that estimate.
//   - gain solver: at each solve, the REFERENCE that the recorded GAINS names (reference_seq) is
//     the reference input, recomputed by the replay's controller.
//   - REFERENCE names command_seq, params_seq and trajectory_seq; GAINS names state_seq and
//     params_seq; RATE_CMD names state_seq, gains_seq and reference_seq. These are compared like
//     every other field, so a tick that saw other inputs than the recorded one is reported.
// With the same code and the same pairing, every output is identical bit for bit.

#include <cstdint>
#include <map>
#include <optional>
#include <tuple>
#include <vector>

#include "sdlqr/controller/controller_core.hpp"
#include "sdlqr/controller/controller_params.hpp"
#include "sdlqr/estimator/estimator_core.hpp"
#include "sdlqr/gains/gains_core.hpp"
#include "sdlqr/gains/gains_params.hpp"
#include "sdlqr/health/validate.hpp"
#include "sdlqr/health/watchdog.hpp"
#include "sdlqr/math/lqr_params.hpp"
#include "sdlqr/messages/outbox.hpp"
#include "sdlqr/messages/ports.hpp"
#include "sdlqr/replay/recorded_flight.hpp"

namespace sdlqr::replay {

struct ReplayParams {
  estimator::EstimatorParams estimator;
  LqrParams lqr;
  controller::ControllerParams controller;
  gains::GainsParams gains;
  FaultParams faults;
  ValidationLimits validation;
};

// How the pairing was honoured.
struct PairingStats {
  int64_t gains_from_replay = 0;    // GAINS named by a RATE_CMD, taken from the recomputed ones
  int64_t gains_from_record = 0;    // named GAINS the replay did not recompute: the recorded one fed
  int64_t references_from_replay = 0;
  int64_t references_from_record = 0;
  int64_t solves_unpaired = 0;      // a solve at an estimate no recorded GAINS names
  int64_t estimates_without_record = 0;  // recomputed STATE_EST of a seq absent from the log
  int64_t rejected = 0;             // inputs refused by the cores (see the cores' health)
  int64_t solve_failures = 0;
  // STATE_EST the process did not receive on the bus (its queue holds one message), inferred
  // from the recorded outputs: the controller ticked later, the solver solved on a later one.
  int64_t estimates_missed_by_controller = 0;
  int64_t estimates_missed_by_solver = 0;
  // Recorded STATE_EST and GAINS the replay did not compute (forged, replayed, another process's):
  // fed to the cores as they reached them on the bus.
  int64_t foreign_estimates = 0;
  int64_t foreign_gains = 0;
};

class Recomputation {
 public:
  // `flight` must outlive this object. Throws std::invalid_argument on invalid parameters.
  Recomputation(const ReplayParams& params, const RecordedFlight& flight);

  bool done() const { return next_ >= flight_.order.size(); }
  // Simulation time of the next input (for pacing against wall time).
  int64_t nextUtime() const { return flight_.utimeAt(flight_.order[next_]); }
  // Handles the next input of the log; new outputs are appended to outputs().
  void step();
  // Hands over estimates still waiting for their place in the log. Call once done().
  void finish();
  void runToEnd() {
    while (!done()) step();
    finish();
  }

  const ReplayOutputs& outputs() const { return outputs_; }
  const PairingStats& pairing() const { return pairing_; }
  const estimator::EstimatorCore& estimator() const { return estimator_; }
  const gains::GainsCore& gains() const { return gains_; }
  const controller::ControllerCore& controller() const { return controller_; }
  std::size_t inputsHandled() const { return next_; }

 private:
  // What the cores publish (STATE_EST, GAINS, RATE_CMD, REFERENCE), taken on by the replay.
  struct TakeOutput {
    Recomputation* replay;
    template <class Msg>
    void operator()(const Msg& m) const {
      replay->onOutput(m);
    }
  };
  template <class Msg>
  void onOutput(const Msg&) {}  // the three cores publish nothing else
  void onOutput(const StateEstimate& m) { onEstimate(m); }
  void onOutput(const GainSet& m);
  void onOutput(const RateCommand& m);
  void onOutput(const Reference& m);

  void onEstimate(const StateEstimate& estimate);
  void feedWallTime(int64_t utime);
  void onRecordedEstimate(const StateEstimate& recorded);
  void onRecordedGains(const GainSet& recorded);
  bool solvedByReplay(const GainSet& recorded) const;
  void judgeGainsHeardEarly(int64_t handed_over_seq);
  bool aheadOfItsImu(const StateEstimate& recorded) const;
  void onUndecodable(const UndecodableInput& input);
  void updateRejected();
  void feedNamedReference(const StateEstimate& estimate);
  void handOver(const StateEstimate& estimate);
  void controllerOnEstimate(const StateEstimate& estimate);
  bool missedByController(const StateEstimate& estimate, const RateCommand& recorded) const;
  void gainsOnEstimate(const StateEstimate& estimate);
  using SeqIndex = std::map<int64_t, std::size_t>;  // seq -> index into a series
  template <class T>
  static const T* named(int64_t seq, const SeqIndex& replayed, const std::vector<T>& replayed_series,
                        const SeqIndex& recorded, const std::vector<T>& recorded_series, int64_t& from_replay,
                        int64_t& from_record);
  void feedNamedGains(int64_t gains_seq);
  void deliverCommandsBefore(const StateEstimate& estimate);
  bool ticksWithoutHeardCommands(const StateEstimate& estimate) const;
  void applyCommand(std::size_t index);
  void onRecordedTrajectory(std::size_t index);
  void deliverTrajectoriesNamedBy(int64_t reference_seq);
  // The recomputed cores, in the order of the in-process loop (the solver before the controller).
  auto cores() { return std::tie(estimator_, gains_, controller_); }
  template <class Msg>
  void deliver(const Msg& m);
  template <class Core>
  void rejectIfTaken(Core& core, const UndecodableInput& input);

  const RecordedFlight& flight_;
  std::size_t next_ = 0;
  ReplayOutputs outputs_;
  PairingStats pairing_;

  estimator::EstimatorCore estimator_;
  gains::GainsCore gains_;
  int64_t solve_period_us_;  // as GainScheduler's grid
  controller::ControllerCore controller_;
  int64_t tick_period_us_;   // as the controller's grid
  OutboxTo<TakeOutput> outbox_{TakeOutput{this}};

  // Recomputed estimates waiting for the log position of the recorded STATE_EST of their seq.
  std::map<int64_t, StateEstimate> waiting_;
  int64_t handed_over_up_to_ = -1;    // highest recorded STATE_EST seq whose place has passed
  int64_t last_recomputed_seq_ = -1, last_recomputed_utime_ = -1;
  std::size_t next_tick_ = 0;         // index of the next recorded RATE_CMD
  std::size_t next_solve_ = 0;        // index of the next recorded GAINS
  int64_t fed_gains_seq_ = -1;
  std::vector<std::size_t> heard_commands_;  // COMMANDs the recorder heard, not yet delivered
  std::vector<bool> command_delivered_;      // by index into flight_.command
  int64_t applied_command_seq_ = -1;         // highest seq delivered
  // TRAJECTORY seq -> seq of the first recorded REFERENCE that tracks it.
  std::map<int64_t, int64_t> first_reference_tracking_;
  std::vector<std::size_t> held_trajectories_;  // heard before the tick that first tracked them
  // Recomputed outputs by seq, for the pairing.
  SeqIndex replayed_gains_, replayed_reference_;
  std::vector<GainSet> gains_heard_early_;  // recorded before the estimate they were solved at
  SeqIndex recorded_gains_, recorded_reference_, recorded_estimate_;
};

}  // namespace sdlqr::replay
