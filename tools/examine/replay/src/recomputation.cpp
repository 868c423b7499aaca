#include "sdlqr/replay/recomputation.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <type_traits>

namespace sdlqr::replay {

int64_t RecordedFlight::utimeAt(const LogPosition& p) const {
  const auto i = static_cast<std::size_t>(p.index);
  switch (p.kind) {
    case InputKind::kImu: return imu[i].utime;
    case InputKind::kVioPose: return vio_pose[i].utime;
    case InputKind::kStateEstimate: return state_estimate[i].utime;
    case InputKind::kCommand: return command[i].utime;
    case InputKind::kTrajectory: return trajectory[i].utime;
    case InputKind::kParams: return params[i].utime;
    case InputKind::kGains: return gains[i].utime;
    case InputKind::kUndecodable: return undecodable[i].utime;
  }
  return 0;
}

namespace {

// How far ahead of the newest recomputed estimate the recorder can hear one, or a solve at one.
constexpr int64_t kMaxSeqsAhead = 2;

template <class T>
std::map<int64_t, std::size_t> indexBySeq(const std::vector<T>& series) {
  std::map<int64_t, std::size_t> index;
  for (std::size_t i = 0; i < series.size(); ++i) index.emplace(series[i].seq, i);
  return index;
}

const estimator::EstimatorParams& checked(const ReplayParams& p) {
  if (!p.lqr.valid()) throw std::invalid_argument("lqr: " + p.lqr.invalidReason());
  if (!p.controller.valid()) throw std::invalid_argument("controller: " + p.controller.invalidReason());
  if (!p.gains.valid()) throw std::invalid_argument("gains: " + p.gains.invalidReason());
  if (!p.faults.valid()) throw std::invalid_argument("faults: " + p.faults.invalidReason());
  return p.estimator;
}

}  // namespace

Recomputation::Recomputation(const ReplayParams& params, const RecordedFlight& flight)
    : flight_(flight),
      estimator_(checked(params)),
      gains_(params.lqr, params.gains, params.faults, params.validation),
      solve_period_us_(static_cast<int64_t>(1e6 / params.gains.rate_hz + 0.5)),
      controller_(params.lqr, params.controller, params.faults, params.validation),
      tick_period_us_(static_cast<int64_t>(1e6 / params.controller.rate_hz + 0.5)),
      command_delivered_(flight.command.size(), false),
      recorded_gains_(indexBySeq(flight.gains)),
      recorded_reference_(indexBySeq(flight.reference)),
      recorded_estimate_(indexBySeq(flight.state_estimate)) {
  for (const Reference& r : flight.reference) {
    if (r.trajectory_seq >= 0) first_reference_tracking_.emplace(r.trajectory_seq, r.seq);
  }
}

void Recomputation::step() {
  const LogPosition p = flight_.order[next_++];
  const auto i = static_cast<std::size_t>(p.index);
  feedWallTime(flight_.utimeAt(p));
  switch (p.kind) {
    case InputKind::kImu: deliver(flight_.imu[i]); break;
    case InputKind::kVioPose: deliver(flight_.vio_pose[i]); break;
    case InputKind::kStateEstimate: onRecordedEstimate(flight_.state_estimate[i]); break;
    case InputKind::kCommand: heard_commands_.push_back(i); break;
    case InputKind::kTrajectory: onRecordedTrajectory(i); break;
    case InputKind::kParams: deliver(flight_.params[i]); break;
    case InputKind::kGains: onRecordedGains(flight_.gains[i]); break;
    case InputKind::kUndecodable: onUndecodable(flight_.undecodable[i]); break;
  }
  updateRejected();
}

void Recomputation::finish() {
  deliverTrajectoriesNamedBy(std::numeric_limits<int64_t>::max());
  for (const auto& [seq, estimate] : waiting_) handOver(estimate);
  waiting_.clear();
  judgeGainsHeardEarly(std::numeric_limits<int64_t>::max());
  for (std::size_t i : heard_commands_) applyCommand(i);
  heard_commands_.clear();
  updateRejected();
}

// Wall time is simulation time in the replay: the watchdogs see the recorded stream's pace.
void Recomputation::feedWallTime(int64_t utime) {
  const double now_s = 1e-6 * static_cast<double>(utime);
  std::apply([&](auto&... core) { (ports::feedWallTime(core, now_s), ...); }, cores());
}

void Recomputation::updateRejected() {
  pairing_.rejected = estimator_.health().rejected() + gains_.health().rejected() + controller_.health().rejected();
  pairing_.solve_failures = gains_.health().errors();
}

// sdlqr-estimator published it: it waits for the place of the recorded STATE_EST of its seq.
void Recomputation::onEstimate(const StateEstimate& estimate) {
  outputs_.state_estimate.push_back(estimate);
  last_recomputed_seq_ = estimate.seq;
  last_recomputed_utime_ = estimate.utime;
  if (estimate.seq <= handed_over_up_to_) {
    ++pairing_.estimates_without_record;  // its place in the log has passed (or never was)
    handOver(estimate);
  } else {
    waiting_.emplace(estimate.seq, estimate);
  }
}

// The recorded STATE_EST marks where the controller and the solver received this seq. One the
// replay did not compute (a forged, replayed or foreign estimate) reached them as it was.
void Recomputation::onRecordedEstimate(const StateEstimate& recorded) {
  const auto ours = waiting_.find(recorded.seq);
  if ((ours == waiting_.end() || ours->second.utime != recorded.utime) && !aheadOfItsImu(recorded)) {
    ++pairing_.foreign_estimates;
    deliver(recorded);
    return;
  }
  handed_over_up_to_ = std::max(handed_over_up_to_, recorded.seq);
  while (!waiting_.empty() && waiting_.begin()->first <= recorded.seq) {
    const StateEstimate estimate = waiting_.begin()->second;
    waiting_.erase(waiting_.begin());
    handOver(estimate);
  }
}

// On two cores the recorder may hear an estimate before the IMU sample that completed it (each
// CPU delivers its own multicast backlog): the next seq or the one after, a little later than
// the newest recomputed estimate, is that, and takes its place when it is recomputed.
bool Recomputation::aheadOfItsImu(const StateEstimate& recorded) const {
  constexpr int64_t kMaxAheadUs = 50'000;
  return recorded.seq > last_recomputed_seq_ && recorded.seq <= last_recomputed_seq_ + kMaxSeqsAhead &&
         recorded.utime > last_recomputed_utime_ && recorded.utime <= last_recomputed_utime_ + kMaxAheadUs;
}

// A recorded GAINS the replay did not solve (forged, or from another solver) reached the
// controller on the bus: it is judged by the controller's core here too. The recorder reads
// GAINS and STATE_EST on sockets of their own, so on a busy machine it may hear a solve before
// the estimate it was solved at, even before the IMU sample that completed that estimate (see
// aheadOfItsImu): such a one is judged once that estimate is handed over.
void Recomputation::onRecordedGains(const GainSet& recorded) {
  if (solvedByReplay(recorded)) return;
  const bool estimate_not_handed_over = recorded.state_seq > std::min(handed_over_up_to_, last_recomputed_seq_);
  if (estimate_not_handed_over && recorded.state_seq <= last_recomputed_seq_ + kMaxSeqsAhead) {
    gains_heard_early_.push_back(recorded);
    return;
  }
  ++pairing_.foreign_gains;
  deliver(recorded);
}

bool Recomputation::solvedByReplay(const GainSet& recorded) const {
  const auto ours = replayed_gains_.find(recorded.seq);
  return ours != replayed_gains_.end() && outputs_.gains[ours->second].utime == recorded.utime;
}

// Those heard early whose estimate (or a later one) has been handed over: foreign if the
// replay did not solve them by now.
void Recomputation::judgeGainsHeardEarly(int64_t handed_over_seq) {
  auto judged = std::remove_if(gains_heard_early_.begin(), gains_heard_early_.end(), [&](const GainSet& g) {
    if (g.state_seq > handed_over_seq) return false;
    if (!solvedByReplay(g)) {
      ++pairing_.foreign_gains;
      deliver(g);
    }
    return true;
  });
  gains_heard_early_.erase(judged, gains_heard_early_.end());
}

// Refused by the bus's decode step: counted by the cores whose ports take the channel, as on the bus.
void Recomputation::onUndecodable(const UndecodableInput& input) {
  std::apply([&](auto&... core) { (rejectIfTaken(core, input), ...); }, cores());
}

template <class Core>
void Recomputation::rejectIfTaken(Core& core, const UndecodableInput& input) {
  if (ports::takesStream<Core>(input.stream)) core.health().reject(input.stream, input.reason);
}

// A message every core whose ports take it receives as it was (the routing of the in-process
// loop): the inputs no output of the flight names (IMU, VIO_POSE, PARAMS) and foreign messages.
template <class Msg>
void Recomputation::deliver(const Msg& m) {
  std::apply([&](auto&... core) { (ports::deliver(core, m, outbox_), ...); }, cores());
}

// The solver first: a solve at this estimate can only use references of earlier ticks (the
// REFERENCE of this estimate's tick is sent after the estimate), while this estimate's tick may
// name the GAINS solved at it (when the solver was quicker than the controller).
void Recomputation::handOver(const StateEstimate& estimate) {
  gainsOnEstimate(estimate);
  if (!gains_heard_early_.empty()) judgeGainsHeardEarly(estimate.seq);
  controllerOnEstimate(estimate);
}

// The output of `seq` a recorded one names: recomputed if the replay has it (counted in
// from_replay), else as recorded (from_record); nullptr if neither.
template <class T>
const T* Recomputation::named(int64_t seq, const SeqIndex& replayed, const std::vector<T>& replayed_series,
                              const SeqIndex& recorded, const std::vector<T>& recorded_series, int64_t& from_replay,
                              int64_t& from_record) {
  if (auto it = replayed.find(seq); it != replayed.end()) {
    ++from_replay;
    return &replayed_series[it->second];
  }
  if (auto it = recorded.find(seq); it != recorded.end()) {
    ++from_record;
    return &recorded_series[it->second];
  }
  return nullptr;
}

// The GAINS a recorded tick names.
void Recomputation::feedNamedGains(int64_t gains_seq) {
  if (gains_seq < 0 || gains_seq == fed_gains_seq_) return;
  const GainSet* gains = named(gains_seq, replayed_gains_, outputs_.gains, recorded_gains_, flight_.gains,
                               pairing_.gains_from_replay, pairing_.gains_from_record);
  if (gains == nullptr) return;
  controller_.onGains(*gains);
  fed_gains_seq_ = gains_seq;
}

// True when the recorded tick shows the controller cannot have received `estimate` (a tick is
// computed from the last estimate before a grid point, carried forward, or on the first one at
// or after it):
//  - feeding it would tick earlier in the same grid slot than the recording did,
//  - feeding it would tick in a slot the recording has no tick in, while the controller was
//    ticking (a tick recorded before): it missed every estimate of that slot, or
//  - the recorded tick is carried forward from the next estimate over a longer interval than
//    the one from this estimate: the controller's previous estimate was older than this one.
bool Recomputation::missedByController(const StateEstimate& estimate, const RateCommand& recorded) const {
  const int64_t tick_utime = controller_.lqr().tickUtimeFor(estimate);
  if (tick_utime >= 0) {
    const int64_t next_grid = (tick_utime / tick_period_us_ + 1) * tick_period_us_;
    const bool ticking = next_tick_ > 0;
    const bool later_in_slot = recorded.utime > tick_utime && recorded.utime < next_grid;
    const bool slot_skipped = ticking && recorded.utime >= next_grid;
    return (later_in_slot || slot_skipped) && recorded.state_seq > estimate.seq;
  }
  if (recorded.state_seq != estimate.seq + 1) return false;
  const auto next = recorded_estimate_.find(estimate.seq + 1);
  if (next == recorded_estimate_.end()) return false;
  const int64_t next_utime = flight_.state_estimate[next->second].utime;
  const bool carried_forward = recorded.utime > next_utime;
  return carried_forward && next_utime + (next_utime - estimate.utime) <= recorded.utime;
}

// The controller's STATE_EST, with the GAINS of the next recorded tick fed first.
void Recomputation::controllerOnEstimate(const StateEstimate& estimate) {
  deliverCommandsBefore(estimate);
  const std::vector<RateCommand>& ticks = flight_.rate_command;
  // A tick is computed from estimate state_seq, carried forward, on the arrival of the next one.
  while (next_tick_ < ticks.size() && ticks[next_tick_].state_seq < estimate.seq - 1) ++next_tick_;
  if (next_tick_ < ticks.size() && ticks[next_tick_].state_seq <= estimate.seq) {
    feedNamedGains(ticks[next_tick_].gains_seq);
    deliverTrajectoriesNamedBy(ticks[next_tick_].reference_seq);
  }
  // The controller's STATE_EST queue holds one message: a busy controller misses estimates, and
  // a tick then comes later than the grid point (on the next estimate it did receive). An
  // estimate that would make a tick earlier than the recorded one was not received: skip it.
  if (next_tick_ < ticks.size() && missedByController(estimate, ticks[next_tick_])) {
    ++pairing_.estimates_missed_by_controller;
    return;
  }
  controller_.onStateEstimate(estimate, outbox_);
}

void Recomputation::onOutput(const RateCommand& m) {
  outputs_.rate_command.push_back(m);
  const std::vector<RateCommand>& ticks = flight_.rate_command;
  while (next_tick_ < ticks.size() && ticks[next_tick_].seq <= m.seq) ++next_tick_;
}

void Recomputation::onOutput(const Reference& m) {
  replayed_reference_[m.seq] = outputs_.reference.size();
  outputs_.reference.push_back(m);
}

// solve_us is the solver's wall time, measured by the process: not recomputed.
void Recomputation::onOutput(const GainSet& m) {
  replayed_gains_[m.seq] = outputs_.gains.size();
  outputs_.gains.push_back(m);
}

// The solver's STATE_EST, with the REFERENCE the recorded solve names.
void Recomputation::gainsOnEstimate(const StateEstimate& estimate) {
  const gains::GainScheduler& scheduler = gains_.scheduler();
  if (estimate.status != EstimatorStatus::kInitializing) {
    const std::vector<GainSet>& solves = flight_.gains;
    while (next_solve_ < solves.size() && solves[next_solve_].state_seq < estimate.seq) ++next_solve_;
    // The solver solves on the first estimate it receives at or after each grid point; when the
    // recorded solve names a later one, this estimate was lost in its one-message queue.
    if (next_solve_ < solves.size() && solves[next_solve_].state_seq > estimate.seq && scheduler.isDue(estimate) &&
        solves[next_solve_].utime < (estimate.utime / solve_period_us_ + 1) * solve_period_us_) {
      ++pairing_.estimates_missed_by_solver;
      return;
    }
    if (scheduler.isDue(estimate)) feedNamedReference(estimate);
  }
  gains_.onStateEstimate(estimate, outbox_);
}

void Recomputation::feedNamedReference(const StateEstimate& estimate) {
  const std::vector<GainSet>& solves = flight_.gains;
  if (next_solve_ >= solves.size() || solves[next_solve_].state_seq != estimate.seq) {
    ++pairing_.solves_unpaired;
    return;
  }
  const Reference* reference =
      named(solves[next_solve_].reference_seq, replayed_reference_, outputs_.reference, recorded_reference_,
            flight_.reference, pairing_.references_from_replay, pairing_.references_from_record);
  if (reference != nullptr) gains_.onReference(*reference);
}

// COMMAND and STATE_EST race on the bus like GAINS do: the REFERENCE of the tick computed from
// this estimate names the last COMMAND the controller had handled. Every COMMAND heard so far up
// to that one is delivered in log order (re-sends and replayed copies too: the core judges
// them), then those the recorder heard later, up to the named one.
void Recomputation::deliverCommandsBefore(const StateEstimate& estimate) {
  const std::vector<RateCommand>& ticks = flight_.rate_command;
  std::size_t t = next_tick_;
  while (t < ticks.size() && ticks[t].state_seq < estimate.seq) ++t;
  const auto reference = t < ticks.size() && ticks[t].state_seq == estimate.seq
                             ? recorded_reference_.find(ticks[t].reference_seq)
                             : recorded_reference_.end();
  if (reference == recorded_reference_.end()) {
    // No tick names this estimate. The COMMANDs heard wait for the tick that names them (the
    // controller may have heard them later than the recorder: a TAKEOFF delivered now would make
    // a tick the recording lacks), unless without them this estimate would tick (one that stops
    // the ticks, a LAND's touch-down): then in the recorder's order.
    if (!heard_commands_.empty() && !ticksWithoutHeardCommands(estimate)) return;
    for (std::size_t i : heard_commands_) applyCommand(i);
    heard_commands_.clear();
    return;
  }
  const int64_t named = flight_.reference[reference->second].command_seq;
  for (std::size_t i : heard_commands_) {
    if (flight_.command[i].seq <= named) applyCommand(i);
  }
  for (std::size_t i = 0; i < flight_.command.size(); ++i) {  // in log order, also those heard later
    const int64_t seq = flight_.command[i].seq;
    if (!command_delivered_[i] && seq > applied_command_seq_ && seq <= named) applyCommand(i);
  }
  heard_commands_.erase(std::remove_if(heard_commands_.begin(), heard_commands_.end(),
                                       [&](std::size_t i) { return command_delivered_[i]; }),
                        heard_commands_.end());
}

// On a copy of the controller's core: does `estimate` tick?
bool Recomputation::ticksWithoutHeardCommands(const StateEstimate& estimate) const {
  controller::ControllerCore trial = controller_;
  bool ticked = false;
  OutboxTo discard([&](const auto& m) {
    if constexpr (std::is_same_v<std::decay_t<decltype(m)>, RateCommand>) ticked = true;
  });
  trial.onStateEstimate(estimate, discard);
  return ticked;
}

// Each recorded COMMAND reaches the controller's core once, at its delivery.
void Recomputation::applyCommand(std::size_t index) {
  if (command_delivered_[index]) return;
  command_delivered_[index] = true;
  const Command& command = flight_.command[index];
  applied_command_seq_ = std::max(applied_command_seq_, command.seq);
  controller_.onCommand(command);
}

// TRAJECTORY and STATE_EST race on the bus like COMMAND does: one the recorder heard before the
// next tick, but which only a later tick's REFERENCE tracks, reached the controller after that
// tick; it is held until the tick that tracks it. One no REFERENCE tracks (refused, or never
// started) is delivered where the recorder heard it.
void Recomputation::onRecordedTrajectory(std::size_t index) {
  const auto tracked = first_reference_tracking_.find(flight_.trajectory[index].seq);
  const std::vector<RateCommand>& ticks = flight_.rate_command;
  const bool tracked_later = tracked != first_reference_tracking_.end() && next_tick_ < ticks.size() &&
                             ticks[next_tick_].reference_seq < tracked->second;
  if (tracked_later || !held_trajectories_.empty()) {
    held_trajectories_.push_back(index);  // behind a held one: the controller hears them in order
    return;
  }
  controller_.onTrajectory(flight_.trajectory[index]);
}

// The held trajectories up to the last one first tracked by REFERENCE `reference_seq` or earlier.
void Recomputation::deliverTrajectoriesNamedBy(int64_t reference_seq) {
  std::size_t last = 0;  // one past the last to deliver
  for (std::size_t k = 0; k < held_trajectories_.size(); ++k) {
    const auto tracked = first_reference_tracking_.find(flight_.trajectory[held_trajectories_[k]].seq);
    if (tracked != first_reference_tracking_.end() && tracked->second <= reference_seq) last = k + 1;
  }
  for (std::size_t k = 0; k < last; ++k) controller_.onTrajectory(flight_.trajectory[held_trajectories_[k]]);
  held_trajectories_.erase(held_trajectories_.begin(), held_trajectories_.begin() + static_cast<std::ptrdiff_t>(last));
}

}  // namespace sdlqr::replay
